// SPDX-License-Identifier: MIT
// Copyright 2026 the MeshFair authors.
#include "tests/save/save_support.h"

#include <fcntl.h>
#include <grp.h>
#include <poll.h>
#include <sched.h>
#include <signal.h>
#include <sys/mount.h>
#include <sys/resource.h>
#include <sys/stat.h>
#include <sys/syscall.h>
#include <sys/wait.h>
#include <unistd.h>

#include <algorithm>
#include <cctype>
#include <cerrno>
#include <charconv>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <fstream>
#include <map>
#include <random>
#include <sstream>
#include <stdexcept>
#include <thread>

namespace meshfair::save_test {

std::string cli_path()
{
    const char* env = std::getenv("MESHFAIR_SAVE_TEST_CLI");
    return env != nullptr && *env != '\0' ? env : MESHFAIR_CLI;
}

std::string strace_path()
{
    const char* path = std::getenv("PATH");
    std::stringstream dirs(path != nullptr ? path : "/usr/bin:/bin");
    std::string dir;
    while (std::getline(dirs, dir, ':'))
    {
        const std::string candidate = (dir.empty() ? "." : dir) + "/strace";
        if (::access(candidate.c_str(), X_OK) == 0)
            return candidate;
    }
    return "";
}

Scratch::Scratch()
{
    static int counter = 0;
    dir_ = fs::temp_directory_path() /
           ("meshfair-save-" + std::to_string(::getpid()) + "-" + std::to_string(counter++));
    fs::remove_all(dir_);
    fs::create_directories(dir_ / "logs");
    fs::permissions(dir_, fs::perms(0755));
}

Scratch::~Scratch()
{
    std::error_code ec;
    fs::remove_all(dir_, ec);
}

std::optional<std::string> try_read(const fs::path& path)
{
    const int fd = ::open(path.c_str(), O_RDONLY | O_CLOEXEC);
    if (fd < 0)
        return std::nullopt;
    std::string data;
    char buffer[65536];
    for (;;)
    {
        const ssize_t n = ::read(fd, buffer, sizeof buffer);
        if (n < 0 && errno == EINTR)
            continue;
        if (n <= 0)
            break;
        data.append(buffer, static_cast<size_t>(n));
    }
    ::close(fd);
    return data;
}

std::string read_bytes(const fs::path& path)
{
    auto data = try_read(path);
    if (!data)
        throw std::runtime_error("cannot read " + path.string() + ": " + std::strerror(errno));
    return *data;
}

void write_bytes(const fs::path& path, std::string_view content)
{
    std::ofstream out(path, std::ios::binary | std::ios::trunc);
    out.write(content.data(), static_cast<std::streamsize>(content.size()));
    if (!out)
        throw std::runtime_error("cannot write test file " + path.string());
}

std::uint64_t fnv1a(std::string_view data)
{
    std::uint64_t h = 14695981039346656037ull;
    for (const char c : data)
    {
        h ^= static_cast<unsigned char>(c);
        h *= 1099511628211ull;
    }
    return h;
}

std::vector<std::string> list_dir(const fs::path& dir)
{
    std::vector<std::string> names;
    for (const auto& entry : fs::directory_iterator(dir))
        names.push_back(entry.path().filename().string());
    std::sort(names.begin(), names.end());
    return names;
}

std::vector<std::string> temps_in(const fs::path& dir)
{
    std::vector<std::string> temps;
    for (const auto& name : list_dir(dir))
        if (name.find(".tmp-") != std::string::npos)
            temps.push_back(name);
    return temps;
}

int remove_temps(const fs::path& dir)
{
    const auto temps = temps_in(dir);
    for (const auto& name : temps)
        fs::remove(dir / name);
    return static_cast<int>(temps.size());
}

std::string grid_obj(int n, unsigned seed)
{
    std::mt19937_64 rng(seed);
    std::uniform_real_distribution<double> jitter(-0.25, 0.25);
    std::string obj = "# grid " + std::to_string(n) + " seed " + std::to_string(seed) + "\n";
    char number[32];
    const auto put = [&](double x) {
        const auto [end, ec] = std::to_chars(number, number + sizeof number, x);
        obj += ' ';
        obj.append(number, end);
    };
    for (int j = 0; j <= n; ++j)
        for (int i = 0; i <= n; ++i)
        {
            obj += 'v';
            put(i + jitter(rng));
            put(j + jitter(rng));
            put(jitter(rng));
            obj += '\n';
        }
    for (int j = 0; j < n; ++j)
        for (int i = 0; i < n; ++i)
        {
            const int v = j * (n + 1) + i + 1;
            obj += "f " + std::to_string(v) + ' ' + std::to_string(v + 1) + ' ' +
                   std::to_string(v + n + 2) + ' ' + std::to_string(v + n + 1) + '\n';
        }
    return obj;
}

std::string Result::describe() const
{
    std::string what =
        signal != 0 ? "killed by signal " + std::to_string(signal) + " (" + strsignal(signal) + ")"
                    : "exit " + std::to_string(code);
    if (timed_out)
        what += " (timed out)";
    return what + "; stderr: " + err;
}

namespace {

int open_log(const fs::path& path)
{
    const int fd = ::open(path.c_str(), O_WRONLY | O_CREAT | O_TRUNC | O_CLOEXEC, 0644);
    if (fd < 0)
        throw std::runtime_error("cannot create " + path.string() + ": " + std::strerror(errno));
    return fd;
}

//! Only async-signal-safe calls from here to exec: the test may have other threads.
[[noreturn]] void child_exit(const char* what)
{
    const int err = errno;
    const char* reason = std::strerror(err);
    (void)!::write(2, what, std::strlen(what));
    (void)!::write(2, ": ", 2);
    (void)!::write(2, reason, std::strlen(reason));
    (void)!::write(2, "\n", 1);
    ::_exit(127);
}

} // namespace

Child::Child(const std::vector<std::string>& argv, const ChildSetup& setup, const fs::path& log_dir)
{
    static int counter = 0;
    const std::string stem =
        "child-" + std::to_string(::getpid()) + "-" + std::to_string(counter++);
    out_ = log_dir / (stem + ".out");
    err_ = log_dir / (stem + ".err");
    std::vector<char*> args;
    for (const auto& a : argv)
        args.push_back(const_cast<char*>(a.c_str()));
    args.push_back(nullptr);
    const int out_fd = open_log(out_);
    const int err_fd = open_log(err_);
    start_ = std::chrono::steady_clock::now();
    pid_ = ::fork();
    if (pid_ == 0)
    {
        if (::dup2(out_fd, 1) < 0 || ::dup2(err_fd, 2) < 0)
            ::_exit(127);
        if (setup.umask)
            ::umask(*setup.umask);
        if (setup.file_size_limit)
        {
            const rlimit limit{*setup.file_size_limit, *setup.file_size_limit};
            if (::setrlimit(RLIMIT_FSIZE, &limit) != 0)
                child_exit("setrlimit");
        }
        if (setup.ignore_sigxfsz)
            ::signal(SIGXFSZ, *setup.ignore_sigxfsz ? SIG_IGN : SIG_DFL);
        if (setup.as_nobody &&
            (::setgroups(0, nullptr) != 0 || ::setresgid(65534, 65534, 65534) != 0 ||
             ::setresuid(65534, 65534, 65534) != 0))
            child_exit("dropping privileges to 65534");
        ::execv(args[0], args.data());
        child_exit(args[0]);
    }
    ::close(out_fd);
    ::close(err_fd);
    if (pid_ < 0)
        throw std::runtime_error(std::string("fork: ") + std::strerror(errno));
    pidfd_ = static_cast<int>(::syscall(SYS_pidfd_open, pid_, 0));
}

Child::~Child()
{
    if (pid_ > 0)
    {
        ::kill(pid_, SIGKILL);
        ::waitpid(pid_, nullptr, 0);
    }
    if (pidfd_ >= 0)
        ::close(pidfd_);
}

bool Child::exited() const
{
    siginfo_t info{};
    return ::waitid(P_PID, static_cast<id_t>(pid_), &info, WEXITED | WNOHANG | WNOWAIT) == 0 &&
           info.si_pid == pid_;
}

Result Child::wait(std::chrono::milliseconds timeout)
{
    Result r;
    const auto deadline = start_ + timeout;
    int status = 0;
    if (pidfd_ >= 0)
    {
        for (;;)
        {
            const auto left = std::chrono::duration_cast<std::chrono::milliseconds>(
                deadline - std::chrono::steady_clock::now());
            pollfd p{pidfd_, POLLIN, 0};
            const int n = ::poll(&p, 1, static_cast<int>(std::max<long long>(0, left.count())));
            if (n < 0 && errno == EINTR)
                continue;
            if (n == 0)
            {
                r.timed_out = true;
                ::kill(pid_, SIGKILL);
            }
            break;
        }
        ::waitpid(pid_, &status, 0);
    }
    else
    {
        while (::waitpid(pid_, &status, WNOHANG) == 0)
        {
            if (std::chrono::steady_clock::now() > deadline)
            {
                r.timed_out = true;
                ::kill(pid_, SIGKILL);
                ::waitpid(pid_, &status, 0);
                break;
            }
            std::this_thread::sleep_for(std::chrono::microseconds(200));
        }
    }
    pid_ = -1;
    r.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start_).count();
    if (WIFEXITED(status))
        r.code = WEXITSTATUS(status);
    else if (WIFSIGNALED(status))
        r.signal = WTERMSIG(status);
    r.out = try_read(out_).value_or("");
    r.err = try_read(err_).value_or("");
    std::error_code ec;
    fs::remove(out_, ec);
    fs::remove(err_, ec);
    return r;
}

namespace {

// A copy of the CLI that uid 65534 may execute: the build tree may sit in a directory
// only root can enter (CI clones into /root).
std::string cli_for_nobody()
{
    static const fs::path dir =
        fs::temp_directory_path() / ("meshfair-save-cli-" + std::to_string(::getpid()));
    static const std::string copy = [] {
        const auto readable = fs::perms::owner_all | fs::perms::group_read | fs::perms::group_exec |
                              fs::perms::others_read | fs::perms::others_exec;
        fs::create_directories(dir);
        fs::permissions(dir, readable);
        const fs::path cli = dir / "meshfair-cli";
        fs::copy_file(cli_path(), cli, fs::copy_options::overwrite_existing);
        fs::permissions(cli, readable);
        std::atexit([] {
            std::error_code ignored;
            fs::remove_all(dir, ignored);
        });
        return cli.string();
    }();
    return copy;
}

} // namespace

Result run(const std::vector<std::string>& argv, const fs::path& log_dir, const ChildSetup& setup,
           std::chrono::milliseconds timeout)
{
    std::vector<std::string> args = argv;
    if (setup.as_nobody && !args.empty() && args[0] == cli_path())
        args[0] = cli_for_nobody();
    Child child(args, setup, log_dir);
    return child.wait(timeout);
}

std::vector<std::string> save_args(const fs::path& in, const fs::path& out)
{
    // One thread: every run must make the same system calls in the same order, and
    // worker threads interleave theirs (futex, rseq) differently each time.
    return {cli_path(),     "smooth", in.string(), "-o",        out.string(),
            "--iterations", "0",      "-q",        "--threads", "1"};
}

// LeakSanitizer cannot run under ptrace; in the sanitizer build the traced CLI runs
// without it (ASan and UBSan stay on). Harmless in other builds.
const char* const kTracedEnvironment = "ASAN_OPTIONS=detect_leaks=0:abort_on_error=1";

std::vector<std::string> under_strace(const std::string& inject,
                                      const std::vector<std::string>& argv)
{
    std::vector<std::string> all{strace_path(), "-f",        "-qq", "-E",   kTracedEnvironment,
                                 "-o",          "/dev/null", "-e",  inject, "--"};
    all.insert(all.end(), argv.begin(), argv.end());
    return all;
}

std::vector<Syscall> trace_syscalls(const std::vector<std::string>& argv, const fs::path& log_dir)
{
    std::vector<Syscall> shortest;
    for (int attempt = 0; attempt < 3; ++attempt)
    {
        const fs::path log = log_dir / ("strace-" + std::to_string(::getpid()) + ".log");
        std::vector<std::string> all{strace_path(),      "-f", "-qq",        "-E",
                                     kTracedEnvironment, "-o", log.string(), "--"};
        all.insert(all.end(), argv.begin(), argv.end());
        const Result r = run(all, log_dir);
        if (r.code != 0)
            throw std::runtime_error("strace run failed: " + r.describe());
        std::vector<Syscall> calls;
        std::map<std::string, int> seen;
        std::istringstream lines(read_bytes(log));
        fs::remove(log);
        std::string line;
        while (std::getline(lines, line))
        {
            size_t i = 0;
            while (i < line.size() && std::isdigit(static_cast<unsigned char>(line[i])))
                ++i;
            while (i < line.size() && line[i] == ' ')
                ++i;
            size_t end = i;
            while (end < line.size() &&
                   (std::isalnum(static_cast<unsigned char>(line[end])) || line[end] == '_'))
                ++end;
            // Skips "--- SIGCHLD ---", "+++ exited +++" and "<... read resumed>" lines.
            if (end == i || end >= line.size() || line[end] != '(')
                continue;
            Syscall call;
            call.name = line.substr(i, end - i);
            call.occurrence = ++seen[call.name];
            call.line = line;
            calls.push_back(std::move(call));
        }
        if (shortest.empty() || calls.size() < shortest.size())
            shortest = std::move(calls);
    }
    return shortest;
}

NamespaceResult in_private_mount_namespace(const std::function<int()>& body)
{
    int pipe_fds[2];
    if (::pipe2(pipe_fds, O_CLOEXEC) != 0)
        throw std::runtime_error(std::string("pipe2: ") + std::strerror(errno));
    const pid_t pid = ::fork();
    if (pid == 0)
    {
        ::close(pipe_fds[0]);
        const auto report = [&](const std::string& message) {
            (void)!::write(pipe_fds[1], message.data(), message.size());
        };
        const auto fail = [&](const std::string& step) {
            report(step + ": " + std::strerror(errno));
            ::_exit(126);
        };
        if (::geteuid() == 0)
        {
            if (::unshare(CLONE_NEWNS) != 0)
                fail("unshare(CLONE_NEWNS) as root");
        }
        else
        {
            // What `unshare -rm` does: become root of a new user namespace.
            const auto uid = ::getuid();
            const auto gid = ::getgid();
            if (::unshare(CLONE_NEWUSER | CLONE_NEWNS) != 0)
                fail("unshare(CLONE_NEWUSER | CLONE_NEWNS) as uid " + std::to_string(uid));
            const auto put = [&](const char* file, const std::string& text) {
                std::ofstream f(file);
                f << text;
                f.close();
                if (!f)
                    fail(std::string("writing ") + file);
            };
            put("/proc/self/setgroups", "deny");
            put("/proc/self/uid_map", "0 " + std::to_string(uid) + " 1");
            put("/proc/self/gid_map", "0 " + std::to_string(gid) + " 1");
        }
        // Mounts made below must not propagate back to the host's namespace. In a chroot
        // "/" is no mount point (EINVAL): there the parent may see a body's mounts while
        // they exist, so every body unmounts what it mounted before it returns.
        if (::mount(nullptr, "/", nullptr, MS_REC | MS_PRIVATE, nullptr) != 0 && errno != EINVAL)
            fail("making / a private mount");
        ::close(pipe_fds[1]);
        int status = 99;
        try
        {
            status = body();
        }
        catch (const std::exception& e)
        {
            std::fprintf(stderr, "namespace body: %s\n", e.what());
        }
        ::_exit(status);
    }
    ::close(pipe_fds[1]);
    NamespaceResult result;
    char buffer[512];
    ssize_t n = 0;
    while ((n = ::read(pipe_fds[0], buffer, sizeof buffer)) > 0)
        result.error.append(buffer, static_cast<size_t>(n));
    ::close(pipe_fds[0]);
    int status = 0;
    ::waitpid(pid, &status, 0);
    result.entered = result.error.empty();
    result.status = WIFEXITED(status) ? WEXITSTATUS(status) : 128 + WTERMSIG(status);
    return result;
}

} // namespace meshfair::save_test
