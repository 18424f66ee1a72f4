// The remainder by multiplication is the remainder: for every divisor the
// consensus model may use and more, on random inputs and on the edges.

#include "video/matte/Remainder.hpp"

#include <gtest/gtest.h>

#include <random>

using namespace arcomp;

TEST(Remainder, equalsTheRemainderOfADivision) {
    std::mt19937 random(2019);
    for (std::uint32_t d = 1; d <= 1000; ++d) {
        const Remainder r(d);
        for (const std::uint32_t x : {0u, 1u, d - 1, d, d + 1, 0x7FFFFFFFu, 0x80000000u, 0xFFFFFFFEu, 0xFFFFFFFFu})
            ASSERT_EQ(r(x), x % d) << x << " % " << d;
        for (int i = 0; i < 2000; ++i) {
            const std::uint32_t x = random();
            ASSERT_EQ(r(x), x % d) << x << " % " << d;
        }
    }
    for (const std::uint32_t d : {65535u, 65536u, 65537u, 0x80000001u, 0xFFFFFFFFu}) {
        const Remainder r(d);
        for (int i = 0; i < 20000; ++i) {
            const std::uint32_t x = random();
            ASSERT_EQ(r(x), x % d) << x << " % " << d;
        }
    }
}
