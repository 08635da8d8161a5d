#pragma once
// A private virtual X server for tests of windowed code (GLFW backend, viewer). Started on a free
// display number, stopped when the object goes away. Tests skip with a clear message when Xvfb
// is not installed (.ci/setup installs it).
#include <signal.h>
#include <sys/types.h>
#include <sys/wait.h>
#include <unistd.h>

#include <chrono>
#include <filesystem>
#include <string>
#include <thread>

namespace vct::test {

class Xvfb {
public:
    Xvfb() {
        if (!std::filesystem::exists("/usr/bin/Xvfb")) return;
        for (int display = 90; display < 140 && pid_ <= 0; ++display) {
            if (std::filesystem::exists("/tmp/.X11-unix/X" + std::to_string(display)) ||
                std::filesystem::exists("/tmp/.X" + std::to_string(display) + "-lock"))
                continue;
            const std::string name = ":" + std::to_string(display);
            const pid_t pid = fork();
            if (pid == 0) {
                execl("/usr/bin/Xvfb", "Xvfb", name.c_str(), "-screen", "0", "1280x800x24", "-nolisten", "tcp",
                      static_cast<char*>(nullptr));
                _exit(127);
            }
            // Ready once its socket exists; give up on this display number if it dies first.
            for (int i = 0; i < 100; ++i) {
                std::this_thread::sleep_for(std::chrono::milliseconds(50));
                if (std::filesystem::exists("/tmp/.X11-unix/X" + std::to_string(display))) {
                    pid_ = pid;
                    display_ = name;
                    break;
                }
                int status = 0;
                if (waitpid(pid, &status, WNOHANG) == pid) break;
            }
            if (pid_ <= 0 && pid > 0) {
                kill(pid, SIGTERM);
                waitpid(pid, nullptr, 0);
            }
        }
    }
    ~Xvfb() {
        if (pid_ > 0) {
            kill(pid_, SIGTERM);
            waitpid(pid_, nullptr, 0);
        }
    }
    Xvfb(const Xvfb&) = delete;
    Xvfb& operator=(const Xvfb&) = delete;

    bool running() const { return pid_ > 0; }
    const std::string& display() const { return display_; }  // e.g. ":93"

private:
    pid_t pid_ = -1;
    std::string display_;
};

}  // namespace vct::test
