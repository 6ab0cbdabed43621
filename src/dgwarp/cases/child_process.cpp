#include "dgwarp/cases/child_process.hpp"

#include <signal.h>
#include <sys/wait.h>
#include <unistd.h>

#include <algorithm>
#include <cerrno>
#include <chrono>
#include <cstring>
#include <exception>
#include <string>
#include <thread>

#include "dgwarp/core/error.hpp"
#include "dgwarp/core/parallel_for.hpp"

namespace dgwarp {

namespace {

// How often the parent looks whether the child has ended: short beside any
// mesh generation worth a child process.
constexpr auto poll_interval = std::chrono::milliseconds(100);
// The child's error message is cut to this many bytes, below the pipe's
// buffer, so that the child never blocks writing it.
constexpr std::size_t max_message = 4000;

// In the child: runs `work` and ends the process (never returns); a message
// of what went wrong goes to `fd`.
[[noreturn]] void run_child(const std::function<void()>& work, int fd) {
    std::string message;
    try {
        work();
        ::_exit(0);
    } catch (const std::exception& e) {
        message = e.what();
    } catch (...) {
        message = "an exception that is not a std::exception";
    }
    message.resize(std::min(message.size(), max_message));
    [[maybe_unused]] const ssize_t written = ::write(fd, message.data(), message.size());
    ::_exit(1);
}

// In the parent: everything the child wrote to `fd` until it closed it.
std::string read_all(int fd) {
    std::string text;
    char buffer[512];
    for (;;) {
        const ssize_t n = ::read(fd, buffer, sizeof buffer);
        if (n > 0) text.append(buffer, static_cast<std::size_t>(n));
        else if (n == 0 || errno != EINTR) return text;
    }
}

}  // namespace

void run_in_child_process(const std::function<void()>& work, int timeout_seconds, const std::string& what) {
    int message_pipe[2];
    if (::pipe(message_pipe) != 0) throw Error(what + ": cannot create a pipe: " + std::strerror(errno));
    const pid_t child = ::fork();
    if (child < 0) {
        const int error = errno;
        ::close(message_pipe[0]);
        ::close(message_pipe[1]);
        throw Error(what + ": cannot start a child process: " + std::strerror(error));
    }
    if (child == 0) {
        ::close(message_pipe[0]);
        // libgomp is not fork-safe: a parallel region in a child forked after
        // the parent ran one waits forever for threads the child does not have
        // (the SU2 writer's blocks did). The child's loops run on its one thread.
        set_num_threads(1);
        run_child(work, message_pipe[1]);
    }
    ::close(message_pipe[1]);

    const auto start = std::chrono::steady_clock::now();
    int status = 0;
    for (;;) {
        const pid_t ended = ::waitpid(child, &status, WNOHANG);
        if (ended == child) break;
        if (ended < 0 && errno != EINTR) {
            const int error = errno;
            ::close(message_pipe[0]);
            throw Error(what + ": cannot wait for the child process: " + std::strerror(error));
        }
        if (std::chrono::steady_clock::now() - start > std::chrono::seconds(timeout_seconds)) {
            ::kill(child, SIGKILL);
            while (::waitpid(child, &status, 0) < 0 && errno == EINTR) {
            }
            ::close(message_pipe[0]);
            throw Error(what + " took more than " + std::to_string(timeout_seconds) + " s");
        }
        std::this_thread::sleep_for(poll_interval);
    }
    const std::string message = read_all(message_pipe[0]);
    ::close(message_pipe[0]);
    if (WIFEXITED(status) && WEXITSTATUS(status) == 0) return;
    if (!message.empty()) throw Error(what + " failed: " + message);
    if (WIFSIGNALED(status))
        throw Error(what + " failed: the child process was killed by signal " + std::to_string(WTERMSIG(status)) +
                    " (" + ::strsignal(WTERMSIG(status)) + ")");
    throw Error(what + " failed: the child process exited with status " + std::to_string(WEXITSTATUS(status)));
}

}  // namespace dgwarp
