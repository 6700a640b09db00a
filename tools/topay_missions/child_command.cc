#include "child_command.h"

#include <fcntl.h>
#include <signal.h>
#include <sys/wait.h>
#include <unistd.h>

#include <cerrno>
#include <chrono>
#include <cstring>
#include <thread>

namespace topay::tools {
namespace {

using Clock = std::chrono::steady_clock;

double SecondsSince(Clock::time_point t) { return std::chrono::duration<double>(Clock::now() - t).count(); }

int ExitCodeOf(int status) {
  if (WIFEXITED(status)) return WEXITSTATUS(status);
  if (WIFSIGNALED(status)) return 128 + WTERMSIG(status);
  return -1;
}

[[noreturn]] void ExecChild(const std::vector<std::string>& argv, const std::string& output_path) {
  sigset_t none;  // the caller may block SIGINT / SIGTERM to poll them; the child gets them
  sigemptyset(&none);
  sigprocmask(SIG_SETMASK, &none, nullptr);
  if (!output_path.empty()) {
    const int fd = open(output_path.c_str(), O_WRONLY | O_CREAT | O_TRUNC | O_CLOEXEC, 0644);
    if (fd < 0) _exit(127);
    dup2(fd, STDOUT_FILENO);
    dup2(fd, STDERR_FILENO);
  }
  std::vector<char*> args;
  for (const std::string& a : argv) args.push_back(const_cast<char*>(a.c_str()));
  args.push_back(nullptr);
  execvp(args[0], args.data());
  const std::string why = "cannot run " + argv[0] + ": " + std::strerror(errno) + "\n";
  [[maybe_unused]] const ssize_t n = write(STDERR_FILENO, why.data(), why.size());
  _exit(127);
}

}  // namespace

ChildCommandResult RunChildCommand(const std::vector<std::string>& argv, const ChildCommandOptions& options) {
  ChildCommandResult result;
  if (argv.empty()) {
    result.error = "no program given";
    return result;
  }
  const pid_t pid = fork();
  if (pid < 0) {
    result.error = "cannot start " + argv[0] + ": fork failed: " + std::strerror(errno);
    return result;
  }
  if (pid == 0) ExecChild(argv, options.output_path);
  const Clock::time_point start = Clock::now();
  std::optional<Clock::time_point> interrupted_at;
  while (true) {
    int status = 0;
    const pid_t done = waitpid(pid, &status, WNOHANG);
    if (done == pid) {
      result.exit_code = ExitCodeOf(status);
      break;
    }
    const bool over_time = options.timeout_s > 0.0 && SecondsSince(start) > options.timeout_s;
    if (!interrupted_at && (over_time || (options.stop_requested && options.stop_requested()))) {
      result.timed_out = over_time;
      kill(pid, SIGINT);
      interrupted_at = Clock::now();
    }
    if (interrupted_at && SecondsSince(*interrupted_at) > 10.0) kill(pid, SIGKILL);
    if (options.on_poll) options.on_poll();
    std::this_thread::sleep_for(std::chrono::duration<double>(options.poll_period_s));
  }
  if (options.on_poll) options.on_poll();
  if (result.exit_code == 127 && !options.output_path.empty()) result.error = "exit code 127 (see " + options.output_path + ")";
  return result;
}

}  // namespace topay::tools
