#pragma once
// An X server for the viewer's tests: Xvfb (Debian's xvfb, which ./sg
// installs) on a display it picks itself (-displayfd), DISPLAY pointing at it
// for the commands the test runs. Missing Xvfb is a failure, not a skip.
#include <fcntl.h>
#include <signal.h>
#include <sys/wait.h>
#include <unistd.h>

#include <chrono>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <string>
#include <thread>

namespace sg::test {

class XvfbDisplay {
 public:
  XvfbDisplay() {
    int fds[2];
    if (pipe(fds) != 0) {
      error_ = "pipe failed";
      return;
    }
    pid_ = fork();
    if (pid_ == 0) {
      close(fds[0]);
      const int null = open("/dev/null", O_WRONLY);
      dup2(null, 2);  // its warnings about /tmp/.X11-unix are not the test's
      const std::string fd = std::to_string(fds[1]);
      execlp("Xvfb", "Xvfb", "-displayfd", fd.c_str(), "-screen", "0", "1280x1024x24", "-nolisten", "tcp",
             static_cast<char*>(nullptr));
      _exit(127);
    }
    close(fds[1]);
    std::string number;
    char c;
    while (read(fds[0], &c, 1) == 1 && c != '\n') number += c;
    close(fds[0]);
    if (number.empty()) {
      error_ = "Xvfb did not start (install Debian's xvfb: ./sg installs it)";
      return;
    }
    display_ = ":" + number;
    setenv("DISPLAY", display_.c_str(), 1);
  }
  ~XvfbDisplay() {
    if (pid_ > 0) {
      kill(pid_, SIGTERM);
      waitpid(pid_, nullptr, 0);
    }
  }
  XvfbDisplay(const XvfbDisplay&) = delete;
  XvfbDisplay& operator=(const XvfbDisplay&) = delete;

  bool ok() const { return !display_.empty(); }
  const std::string& error() const { return error_; }

 private:
  pid_t pid_ = -1;
  std::string display_, error_;
};

// A window manager on DISPLAY, for what only one provides (iconifying a
// window): twm (Debian's twm, which ./sg installs), placing windows itself and
// using the server's built-in "fixed" font. Missing twm is a failure.
class TwmWindowManager {
 public:
  TwmWindowManager() {
    const auto config = std::filesystem::temp_directory_path() / ("sg-twmrc-" + std::to_string(getpid()));
    std::ofstream(config) << "RandomPlacement\nTitleFont \"fixed\"\nResizeFont \"fixed\"\nMenuFont \"fixed\"\n"
                             "IconFont \"fixed\"\nIconManagerFont \"fixed\"\n";
    pid_ = fork();
    if (pid_ == 0) {
      const int null = open("/dev/null", O_WRONLY);
      dup2(null, 1);
      dup2(null, 2);  // its warnings about missing charsets are not the test's
      execlp("twm", "twm", "-f", config.c_str(), static_cast<char*>(nullptr));
      _exit(127);
    }
    // twm has no readiness signal: give it time to take the screen, then check it is still there.
    std::this_thread::sleep_for(std::chrono::milliseconds(500));
    int status = 0;
    if (pid_ < 0 || waitpid(pid_, &status, WNOHANG) != 0) {
      pid_ = -1;
      error_ = "twm did not start (install Debian's twm: ./sg installs it)";
    }
  }
  ~TwmWindowManager() {
    if (pid_ > 0) {
      kill(pid_, SIGTERM);
      waitpid(pid_, nullptr, 0);
    }
  }
  TwmWindowManager(const TwmWindowManager&) = delete;
  TwmWindowManager& operator=(const TwmWindowManager&) = delete;

  bool ok() const { return pid_ > 0; }
  const std::string& error() const { return error_; }

 private:
  pid_t pid_ = -1;
  std::string error_;
};

}  // namespace sg::test
