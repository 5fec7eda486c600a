#pragma once

// A long replay of real operator actions, the same every time for one (count, seed): page switches
// among all the pages, softkeys (Monitor's menus and back, the Param page's tabs, the Program
// page's disks, the tool pages' links), jog taps in STEP mode, override keys, handwheel clicks, MDI
// lines typed and run, and a program loaded and run twice. Jog taps and wheel clicks come in pairs
// that undo each other; the MDI page's F1 runs its line 1, whichever line was typed, so the machine
// wanders slowly (some 400 mm in X and Y over a million actions, within its travel). Used by the replay
// test that compares the fast replay with --eager-replay, and by tests/bench/replay_1m.sh.
#include <cstdint>
#include <cstdio>
#include <functional>
#include <iterator>
#include <string>
#include <vector>

namespace m350::test {

class ReplayMix {
public:
    // `program`: the absolute path of a program to load and run (a few seconds of virtual time),
    // on a disk the Program page shows (--programs its folder).
    ReplayMix(std::uint64_t seed, std::string program) : state_(seed * 2862933555777941757ULL + 1), program_(std::move(program)) {}

    // Calls `out` with each line, `count` actions in all (time marks not counted).
    template <class Out> void write(long count, Out&& out) {
        emit_ = [&out](const std::string& line) { out(line); };
        written_ = 0;
        limit_ = count;
        step(R"("key":"MONITOR")");
        step(R"("key":"CONT_STEP_MPG")"); // CONT -> STEP
        step(R"("key":"STEP_0.01")");
        const long runAt[2] = {count / 3, 2 * count / 3};
        int runs = 0;
        while (written_ < count) {
            if (runs < 2 && written_ >= runAt[runs]) {
                run();
                ++runs;
                continue;
            }
            scene();
        }
        emit_ = {};
    }

    // The program `run` loads: a square and back, about 4 s at 100 %.
    static std::string programText() {
        return "G90 G54 G0 X0 Y0\nG1 X20 F600\nY20\nX0\nY0\nM30\n";
    }

private:
    static constexpr const char* kPages[] = {"monitor", "mdi",    "io",     "probe",   "program",  "param",
                                             "log",     "system", "coord",  "middle",  "record",   "breakrun",
                                             "tools",   "toollife", "breakage", "custom"};
    static constexpr const char* kPageKeys[] = {"MONITOR", "PROGRAM", "PARAM", "IO", "LOG", "SYSTEM", "MDI", "PROBE"};

    std::uint32_t next(std::uint32_t below) {
        state_ = state_ * 6364136223846793005ULL + 1442695040888963407ULL;
        return static_cast<std::uint32_t>((state_ >> 33) % below);
    }

    // One action `body` ("key":"X") a frame or so after the previous one.
    void step(const std::string& body, double gap = 0.02) {
        if (written_ >= limit_) {
            return;
        }
        t_ += gap;
        char time[32];
        std::snprintf(time, sizeof time, "%.3f", t_);
        emit_("{\"t\":" + std::string(time) + "," + body + "}");
        ++written_;
    }

    void wait(double seconds) {
        t_ += seconds;
        char time[32];
        std::snprintf(time, sizeof time, "%.3f", t_);
        emit_("{\"t\":" + std::string(time) + "}");
    }

    static std::string key(const std::string& name) { return "\"key\":\"" + name + "\""; }
    static std::string softkey(int number) { return "\"softkey\":" + std::to_string(number); }

    void scene() {
        switch (next(10)) {
        case 0: // a page by its id, a look up and down its list
        case 1:
            step("\"page\":\"" + std::string(kPages[next(std::size(kPages))]) + "\"");
            step(key("DOWN"));
            step(key("UP"));
            break;
        case 2: // a page key of the panel
            step(key(kPageKeys[next(std::size(kPageKeys))]));
            break;
        case 3: { // Monitor: a menu of softkeys opened and closed again
            step(key("MONITOR"));
            step(softkey(3 + static_cast<int>(next(3))));
            step(key("ESC"));
            break;
        }
        case 4: { // softkeys that only change what a page shows
            switch (next(3)) {
            case 0:
                step("\"page\":\"param\"");
                step(softkey(8));
                step(softkey(7));
                break;
            case 1:
                step("\"page\":\"program\"");
                step(softkey(1));
                step(softkey(1));
                step(softkey(1));
                break;
            default:
                step("\"page\":\"tools\"");
                step(softkey(7 + static_cast<int>(next(2))));
                break;
            }
            break;
        }
        case 5: { // a jog tap in STEP mode and back
            const char axis = "XYZ"[next(3)];
            step(key(std::string("JOG_") + axis + "+"), 0.1);
            step(key(std::string("JOG_") + axis + "-"), 0.1);
            break;
        }
        case 6: { // override keys
            static constexpr const char* overrides[] = {"FRO_UP", "FRO_DOWN", "SRO_UP", "SRO_DOWN", "FRO_100", "SRO_100"};
            step(key(overrides[next(std::size(overrides))]));
            step(key(overrides[next(std::size(overrides))]));
            break;
        }
        case 7: { // handwheel clicks, one detent each way
            const char axis = "XYZ"[next(3)];
            const std::string wheel = std::string("\"wheel\":{\"axis\":\"") + axis + "\",\"step\":1,\"detents\":";
            step(wheel + "1,\"seconds\":0.05}");
            step(wheel + "-1,\"seconds\":0.05}", 0.1);
            break;
        }
        case 8: { // an MDI line typed, kept and run, then its way back
            const char axis = "XY"[next(2)];
            step("\"page\":\"mdi\"");
            for (const char* sign : {"", "-"}) {
                step(std::string("\"text\":\"G91 G1 ") + axis + sign + "0.05 F600\"");
                step(key("ENTER"));
                step(softkey(1), 0.05);
                wait(0.3);
            }
            step(key("ESC"));
            break;
        }
        default: // the cursor keys on whatever page is shown
            step(key(next(2) ? "DOWN" : "UP"));
            break;
        }
    }

    // The program loaded from the Monitor and run to its end, override keys pressed as it runs.
    void run() {
        step(key("MONITOR"));
        step("\"load\":\"" + program_ + "\"");
        step(key("START"), 0.1);
        for (int i = 0; i < 10; ++i) {
            step(key(i % 2 ? "FRO_UP" : "FRO_DOWN"), 0.2);
        }
        wait(6.0);
        step(key("RESET"));
    }

    std::uint64_t state_;
    std::string program_;
    std::function<void(const std::string&)> emit_;
    long written_ = 0;
    long limit_ = 1L << 62;
    double t_ = 0.0;
};

} // namespace m350::test
