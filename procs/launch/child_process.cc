#include "procs/launch/child_process.h"

#include <fcntl.h>
#include <sched.h>
#include <sys/prctl.h>
#include <sys/resource.h>
#include <unistd.h>

#include <cerrno>
#include <cstdlib>
#include <cstring>
#include <filesystem>
#include <sstream>
#include <system_error>

namespace topay::launch {
namespace {

// Runs in the child between fork and exec. The launcher is single-threaded (no lock can be held
// by another thread at fork), so the error paths may build strings.
void WriteAll(int fd, const std::string& text) {
  (void)!write(fd, text.data(), text.size());
}

void ApplyRealtime(const RealtimeSettings& rt) {
  if (rt.nice) setpriority(PRIO_PROCESS, 0, *rt.nice);
  if (!rt.cpus.empty()) {
    cpu_set_t set;
    CPU_ZERO(&set);
    for (const int cpu : rt.cpus) CPU_SET(cpu, &set);
    sched_setaffinity(0, sizeof(set), &set);
  }
  if (rt.fifo_priority) {
    sched_param param{};
    param.sched_priority = *rt.fifo_priority;
    sched_setscheduler(0, SCHED_FIFO, &param);
  }
}

[[noreturn]] void ExecChild(const ProcessSpec& spec, std::vector<char*>& argv, int out_fd,
                            pid_t launcher, const sigset_t& mask) {
  setpgid(0, 0);
  prctl(PR_SET_PDEATHSIG, SIGKILL);
  if (getppid() != launcher) _exit(126);  // the launcher died before the prctl
  const int null_fd = open("/dev/null", O_RDONLY);
  dup2(null_fd, STDIN_FILENO);
  dup2(out_fd, STDOUT_FILENO);
  dup2(out_fd, STDERR_FILENO);
  sigprocmask(SIG_SETMASK, &mask, nullptr);
  if (!spec.working_dir.empty() && chdir(spec.working_dir.c_str()) != 0) {
    WriteAll(STDERR_FILENO, "topay-launch: cannot enter working_dir " + spec.working_dir +
                                ": " + std::strerror(errno) + "\n");
    _exit(127);
  }
  ApplyRealtime(spec.realtime);
  execvp(argv[0], argv.data());
  WriteAll(STDERR_FILENO, "topay-launch: cannot execute " + spec.command + ": " +
                              std::strerror(errno) + "\n");
  _exit(127);
}

}  // namespace

SpawnedChild SpawnChild(const ProcessSpec& spec, const std::map<std::string, std::string>& extra_env,
                        const sigset_t& child_mask) {
  int fds[2];
  if (pipe2(fds, O_CLOEXEC) != 0) throw std::system_error(errno, std::generic_category(), "pipe2");
  // Everything the child needs is prepared before fork (no allocation after it).
  std::vector<std::string> env_strings;
  for (char** e = environ; *e != nullptr; ++e) {
    const std::string entry = *e;
    const std::string key = entry.substr(0, entry.find('='));
    if (!spec.env.contains(key) && !extra_env.contains(key)) env_strings.push_back(entry);
  }
  for (const auto& [key, value] : extra_env) env_strings.push_back(key + "=" + value);
  for (const auto& [key, value] : spec.env) env_strings.push_back(key + "=" + value);
  std::vector<char*> envp;
  for (std::string& s : env_strings) envp.push_back(s.data());
  envp.push_back(nullptr);
  std::vector<std::string> args = {spec.command};
  args.insert(args.end(), spec.args.begin(), spec.args.end());
  std::vector<char*> argv;
  for (std::string& a : args) argv.push_back(a.data());
  argv.push_back(nullptr);

  const pid_t launcher = getpid();
  const pid_t pid = fork();
  if (pid < 0) {
    close(fds[0]);
    close(fds[1]);
    throw std::system_error(errno, std::generic_category(), "fork");
  }
  if (pid == 0) {
    close(fds[0]);
    environ = envp.data();
    ExecChild(spec, argv, fds[1], launcher, child_mask);
  }
  setpgid(pid, pid);  // also here: no race with a kill(-pid) right after fork
  close(fds[1]);
  fcntl(fds[0], F_SETFL, fcntl(fds[0], F_GETFL) | O_NONBLOCK);
  return {pid, fds[0]};
}

std::vector<std::string> CheckRealtime(const ProcessSpec& spec, pid_t pid) {
  std::vector<std::string> warnings;
  const RealtimeSettings& rt = spec.realtime;
  if (rt.nice) {
    errno = 0;
    const int nice = getpriority(PRIO_PROCESS, pid);
    if (errno == 0 && nice != *rt.nice) {
      warnings.push_back("nice " + std::to_string(*rt.nice) + " not applied (got " +
                         std::to_string(nice) + "; negative levels need CAP_SYS_NICE)");
    }
  }
  if (rt.fifo_priority && sched_getscheduler(pid) != SCHED_FIFO) {
    warnings.push_back("SCHED_FIFO priority " + std::to_string(*rt.fifo_priority) +
                       " not applied (needs CAP_SYS_NICE or an RLIMIT_RTPRIO allowance)");
  }
  if (!rt.cpus.empty()) {
    cpu_set_t set;
    CPU_ZERO(&set);
    bool same = sched_getaffinity(pid, sizeof(set), &set) == 0;
    for (const int cpu : rt.cpus) same = same && CPU_ISSET(cpu, &set);
    if (!same || CPU_COUNT(&set) != static_cast<int>(rt.cpus.size())) {
      warnings.push_back("CPU affinity not applied (CPUs missing or not allowed)");
    }
  }
  return warnings;
}

std::string ResolveCommand(const std::string& command) {
  namespace fs = std::filesystem;
  auto executable = [](const fs::path& p) { return access(p.c_str(), X_OK) == 0 && !fs::is_directory(p); };
  if (command.find('/') != std::string::npos) return executable(command) ? command : "";
  const char* path = std::getenv("PATH");
  std::stringstream dirs(path != nullptr ? path : "/usr/bin:/bin");
  std::string dir;
  while (std::getline(dirs, dir, ':')) {
    const fs::path candidate = fs::path(dir.empty() ? "." : dir) / command;
    if (executable(candidate)) return candidate.string();
  }
  return "";
}

}  // namespace topay::launch
