// SPDX-License-Identifier: MIT
// Copyright 2026 the MeshFair authors.
//
// Process plumbing for the save tests: run meshfair-cli (optionally under strace, with a
// file size limit, as `nobody`, or inside a private mount namespace) and look at the
// files it leaves behind.
#pragma once

#include <sys/types.h>

#include <chrono>
#include <cstdint>
#include <filesystem>
#include <functional>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

namespace meshfair::save_test {

namespace fs = std::filesystem;

//! The meshfair-cli under test: $MESHFAIR_SAVE_TEST_CLI if set (to try a deliberately
//! broken build), else the one built beside the tests.
std::string cli_path();

//! strace from PATH, or "" when it is not installed.
std::string strace_path();

//! A fresh directory (mode 0755, so `nobody` can traverse it), removed with its content.
//! Its subdirectory logs/ collects the children's stdout and stderr.
class Scratch
{
public:
    Scratch();
    ~Scratch();
    Scratch(const Scratch&) = delete;
    Scratch& operator=(const Scratch&) = delete;
    const fs::path& dir() const { return dir_; }
    fs::path operator/(const std::string& name) const { return dir_ / name; }
    fs::path logs() const { return dir_ / "logs"; }

private:
    fs::path dir_;
};

//! The whole content, or nullopt when the file cannot be opened.
std::optional<std::string> try_read(const fs::path& path);
//! The whole content; throws when the file cannot be read.
std::string read_bytes(const fs::path& path);
void write_bytes(const fs::path& path, std::string_view content);
//! FNV-1a, 64 bit.
std::uint64_t fnv1a(std::string_view data);

//! Sorted names in `dir`.
std::vector<std::string> list_dir(const fs::path& dir);
//! Names in `dir` that are temporaries of write_file_atomically (contain ".tmp-").
std::vector<std::string> temps_in(const fs::path& dir);
//! Removes those temporaries; returns how many there were.
int remove_temps(const fs::path& dir);

//! An OBJ grid of (n+1)^2 vertices and n^2 quads with pseudo-random coordinates (all 17
//! digits, so the text is long): n = 60 gives about 200 KB.
std::string grid_obj(int n, unsigned seed);

//! What to change in the child between fork and exec.
struct ChildSetup
{
    std::optional<std::uint64_t> file_size_limit; //!< RLIMIT_FSIZE in bytes (ulimit -f)
    std::optional<bool> ignore_sigxfsz;           //!< true: SIG_IGN, false: SIG_DFL
    std::optional<mode_t> umask;
    bool as_nobody = false; //!< setgroups/setresgid/setresuid 65534 (root only)
};

//! How a child ended.
struct Result
{
    int code = -1;  //!< exit status, -1 when killed
    int signal = 0; //!< terminating signal, 0 when it exited
    bool timed_out = false;
    double seconds = 0; //!< wall time from start to reaping
    std::string out, err;
    std::string describe() const; //!< "exit 3" or "killed by SIGKILL", plus stderr
};

//! A started child; its stdout and stderr go to files in `log_dir`.
class Child
{
public:
    Child(const std::vector<std::string>& argv, const ChildSetup& setup, const fs::path& log_dir);
    ~Child();
    Child(const Child&) = delete;
    Child& operator=(const Child&) = delete;
    pid_t pid() const { return pid_; }
    //! True once the process has ended (it is not reaped: wait() collects it).
    bool exited() const;
    //! Waits (killing it with SIGKILL after `timeout`) and collects the result.
    Result wait(std::chrono::milliseconds timeout = std::chrono::seconds(60));

private:
    pid_t pid_ = -1;
    int pidfd_ = -1;
    fs::path out_, err_;
    std::chrono::steady_clock::time_point start_;
};

//! Runs to completion.
Result run(const std::vector<std::string>& argv, const fs::path& log_dir,
           const ChildSetup& setup = {},
           std::chrono::milliseconds timeout = std::chrono::seconds(60));

//! `meshfair-cli smooth IN -o OUT --iterations 0 -q`: reads IN, writes OUT.
std::vector<std::string> save_args(const fs::path& in, const fs::path& out);

//! One system call of a strace log: its name and which invocation of that name it is
//! (1-based), which is what `-e inject=NAME:...:when=N` counts.
struct Syscall
{
    std::string name;
    int occurrence = 0;
    std::string line;
};

//! Every system call of running argv under `strace -f`, in order. The sequence is not
//! quite deterministic (mkostemp calls getrandom again in a few percent of runs), so this
//! traces three runs and returns the shortest, the usual one.
std::vector<Syscall> trace_syscalls(const std::vector<std::string>& argv, const fs::path& log_dir);

//! argv run under strace with one injection expression (`-e inject=...`).
std::vector<std::string> under_strace(const std::string& inject,
                                      const std::vector<std::string>& argv);

//! Runs `body` in a forked child inside a private mount namespace (as root, or in a new
//! user namespace otherwise) and returns its exit status; a failure to enter the
//! namespace is returned as a message instead.
struct NamespaceResult
{
    bool entered = false;
    std::string error; //!< why the namespace could not be entered
    int status = -1;   //!< body's return value
};
NamespaceResult in_private_mount_namespace(const std::function<int()>& body);

} // namespace meshfair::save_test
