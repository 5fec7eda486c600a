#pragma once

#include "core/common/Alarm.h"

#include <cstddef>
#include <string>
#include <vector>

namespace m350::controller {

// What happened to the machine, in order and with its virtual time: every alarm raised and every
// program or MDI run that reached its end. A trainee's attempt is graded on it ("RESET within 15 s
// of the sensor alarm", "no crash", "the change ran to its end"); bounded like the messages.
class RunEvents {
public:
    static constexpr std::size_t kMostKept = 10000;

    struct Event {
        enum class Kind { Alarm, Finished };
        Kind kind = Kind::Alarm;
        double time = 0.0;   // virtual s (SimulatedMachine::time())
        Alarm alarm;         // Kind::Alarm
        std::string program; // Kind::Finished: the file that ran (empty: MDI lines)
    };

    void alarm(double time, const Alarm& raised) { add({Event::Kind::Alarm, time, raised, {}}); }
    void finished(double time, std::string program) { add({Event::Kind::Finished, time, {}, std::move(program)}); }
    const std::vector<Event>& list() const { return events_; }
    std::size_t dropped() const { return dropped_; }

private:
    void add(Event event) {
        if (events_.size() < kMostKept) {
            events_.push_back(std::move(event));
        } else {
            ++dropped_; // an alarm raised in an endless loop keeps the first ones: what the trainee did first
        }
    }
    std::vector<Event> events_;
    std::size_t dropped_ = 0;
};

} // namespace m350::controller
