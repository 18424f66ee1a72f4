#pragma once
// x % d for a divisor known only at run time, by two multiplications
// instead of a division (Lemire, Kaser and Kurz, "Faster remainder by direct
// computation", 2019): the same result for every 32-bit x and d >= 1. The
// consensus model's update draws two or three coin flips a pixel, and each
// division took tens of cycles.
//
//   const Remainder odds(16);
//   if (odds(nextRandom(state)) == 0) ...   // 1 in 16

#include <cstdint>

namespace arcomp {

class Remainder {
public:
    explicit Remainder(std::uint32_t divisor) : divisor_(divisor), magic_(~std::uint64_t{0} / divisor + 1) {}
    std::uint32_t operator()(std::uint32_t x) const {
        const std::uint64_t fraction = magic_ * x;  // x / d's fractional part, in 64 bits
        return static_cast<std::uint32_t>((static_cast<unsigned __int128>(fraction) * divisor_) >> 64);
    }

private:
    std::uint32_t divisor_;
    std::uint64_t magic_;
};

}  // namespace arcomp
