#pragma once
// One OSC bundle being built through liblo, and its bytes on the wire. The
// time tag is "immediately": receivers act on arrival, and two replays of
// one file send the same bytes.
//
//   OscBundle b;
//   b.add("/arcomp/leave").i(7);
//   sender.send(b.bytes());

#include <lo/lo_lowlevel.h>

#include <cstdint>
#include <vector>

namespace arcomp {

class OscBundle {
public:
    // A message in the bundle, taking arguments in order.
    class Message {
    public:
        explicit Message(lo_message m) : m_(m) {}
        Message& i(std::int32_t v);
        Message& f(float v);
        Message& s(const char* v);

    private:
        lo_message m_;
    };

    OscBundle();
    ~OscBundle();
    OscBundle(const OscBundle&) = delete;
    OscBundle& operator=(const OscBundle&) = delete;

    // `path`: a string that outlives the bundle (the address spaces' literals).
    Message add(const char* path);
    std::vector<std::uint8_t> bytes() const;

private:
    lo_bundle bundle_;
};

}  // namespace arcomp
