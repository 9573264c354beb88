// SPDX-License-Identifier: MIT
// Copyright 2026 the MeshFair authors.
//
// Saving that loses nothing: whatever happens to `meshfair-cli ... -o OUT` (a kill at any
// instant or at any system call, a full disk, an I/O error, `ulimit -f`, permissions,
// links), OUT holds its old content or all of the new one. A failure exits 3 with
// "meshfair-cli: cannot write 'OUT': step: reason" and leaves no temporary file.
#include <doctest/doctest.h>
#include <signal.h>
#include <sys/mount.h>
#include <sys/stat.h>
#include <unistd.h>

#include <algorithm>
#include <atomic>
#include <cstdlib>
#include <cstring>
#include <random>
#include <thread>

#include "tests/save/save_support.h"

using namespace meshfair::save_test;

namespace {

constexpr auto npos = std::string::npos;

//! Two inputs whose saved forms differ, and those saved forms (each saved once to a
//! scratch path: what a complete save of that input writes).
struct Meshes
{
    fs::path in_a, in_b;
    std::string out_a, out_b;
};

Meshes make_meshes(const Scratch& s)
{
    Meshes m;
    fs::create_directories(s / "in");
    fs::create_directories(s / "scratch");
    m.in_a = s / "in" / "a.obj";
    m.in_b = s / "in" / "b.obj";
    write_bytes(m.in_a, grid_obj(60, 1));
    write_bytes(m.in_b, grid_obj(60, 2));
    fs::permissions(m.in_a, fs::perms(0644));
    fs::permissions(m.in_b, fs::perms(0644));
    for (const auto& [in, out] : {std::pair{m.in_a, &m.out_a}, std::pair{m.in_b, &m.out_b}})
    {
        const fs::path saved = s / "scratch" / in.filename();
        const Result r = run(save_args(in, saved), s.logs());
        REQUIRE_MESSAGE(r.code == 0, r.describe());
        *out = read_bytes(saved);
    }
    REQUIRE(m.out_a != m.out_b);
    REQUIRE(m.out_a.size() > 200000); // big enough for a kill to land inside the write
    return m;
}

//! A small mesh file, the "old" content a failed save must leave alone.
std::string old_content()
{
    return grid_obj(8, 99);
}

std::string perms_of(const fs::path& path)
{
    char text[8];
    std::snprintf(text, sizeof text, "%04o",
                  static_cast<unsigned>(fs::status(path).permissions()) & 07777u);
    return text;
}

//! What every refused or failed save must do: exit 3, name the target, the step and the
//! reason on stderr, leave the target byte-identical and no temporary file beside it.
void check_refused(const Result& r, const fs::path& target, const std::string& old,
                   const std::string& reason)
{
    INFO(r.describe());
    CHECK(r.code == 3);
    CHECK(r.err.find("meshfair-cli: cannot write '" + target.string() + "'") != npos);
    CHECK(r.err.find(reason) != npos);
    CHECK(try_read(target) == old);
    CHECK(temps_in(target.parent_path()).empty());
}

void require_strace()
{
    REQUIRE_MESSAGE(!strace_path().empty(),
                    "strace is not installed (Debian package 'strace'): the fault injection "
                    "tests need it");
}

// One traced save of mesh B over a target holding mesh A's output: what both
// strace-driven tests start from.
struct TracedSave
{
    Scratch s;
    Meshes m = make_meshes(s);
    fs::path dir = s / "target";
    fs::path target = dir / "mesh.obj";
    const std::string& old = m.out_a;
    const std::string& next = m.out_b;
    std::vector<std::string> args = save_args(m.in_b, target);
    std::vector<Syscall> calls;

    TracedSave()
    {
        require_strace();
        fs::create_directories(dir);
        write_bytes(target, old);
        calls = trace_syscalls(args, s.logs());
        REQUIRE(read_bytes(target) == next);
    }
};

} // namespace

TEST_SUITE("Save")
{
    TEST_CASE("a save writes the whole file, keeps the mode and may overwrite its own input")
    {
        Scratch s;
        const Meshes m = make_meshes(s);
        const fs::path target = s / "out.obj";

        ChildSetup umask027;
        umask027.umask = 027;
        Result r = run(save_args(m.in_a, target), s.logs(), umask027);
        REQUIRE_MESSAGE(r.code == 0, r.describe());
        CHECK(read_bytes(target) == m.out_a);
        CHECK(perms_of(target) == "0640"); // a new file: 0666 & ~umask
        CHECK(temps_in(s.dir()).empty());

        fs::permissions(target, fs::perms(0604));
        r = run(save_args(m.in_b, target), s.logs(), umask027);
        REQUIRE_MESSAGE(r.code == 0, r.describe());
        CHECK(read_bytes(target) == m.out_b);
        CHECK(perms_of(target) == "0604"); // an existing file keeps its mode

        // The input is read whole before the output is written, so IN may be OUT.
        const fs::path self = s / "self.obj";
        fs::copy_file(m.in_a, self);
        r = run(save_args(self, self), s.logs());
        REQUIRE_MESSAGE(r.code == 0, r.describe());
        CHECK(read_bytes(self) == m.out_a);
        r = run({cli_path(), "noise", self.string(), "-o", self.string(), "--sigma", "0.1",
                 "--seed", "3"},
                s.logs());
        REQUIRE_MESSAGE(r.code == 0, r.describe());
        const std::string noisy = read_bytes(self);
        CHECK(noisy != m.out_a);
        r = run({cli_path(), "info", self.string()}, s.logs());
        REQUIRE_MESSAGE(r.code == 0, r.describe());
        CHECK(r.out.find("vertices:          3721") != npos);
        CHECK(r.out.find("faces:             3600") != npos);
        CHECK(temps_in(s.dir()).empty());
    }

    TEST_CASE("SIGKILL at random points of 400 saves: the target is always old or new")
    {
        // Each save is killed at a state it reaches, drawn at random: at once (before the
        // temporary exists), once its temporary holds a random number of the new file's
        // bytes, or once the target is the new file. What the process is doing is waited
        // for, never guessed from a time: a save that ends first is killed after its exit.
        // (Every system call of a save is killed at in the strace case below.)
        Scratch s;
        const Meshes m = make_meshes(s);
        const fs::path dir = s / "target";
        fs::create_directories(dir);
        const fs::path target = dir / "mesh.obj";
        const std::string* outs[2] = {&m.out_a, &m.out_b};
        const fs::path ins[2] = {m.in_a, m.in_b};
        REQUIRE(run(save_args(ins[1], target), s.logs()).code == 0);
        std::string current = read_bytes(target);
        REQUIRE(current == m.out_b);

        const char* seed_env = std::getenv("MESHFAIR_SAVE_TEST_SEED");
        const unsigned seed =
            seed_env != nullptr ? static_cast<unsigned>(std::atoi(seed_env)) : 20260101u;
        std::mt19937 rng(seed);
        std::uniform_int_distribution<int> point(0, 4); // 0 at once, 1-3 in the write, 4 after
        std::uniform_real_distribution<double> fraction(0.0, 1.0);
        // How long the temporary and the target are polled for: a hang guard only.
        constexpr auto kGuard = std::chrono::seconds(60);
        constexpr int kSaves = 400;
        int finished = 0, before = 0, during = 0, after_rename = 0, stale = 0, bad = 0;
        std::string first_bad;
        for (int i = 0; i < kSaves; ++i)
        {
            const int which = i % 2;
            const std::string& next = *outs[which];
            const int at = point(rng);
            const auto bytes = static_cast<std::uintmax_t>(fraction(rng) * next.size());
            Child child(save_args(ins[which], target), {}, s.logs());
            const auto reached = [&] {
                if (at == 4)
                    return try_read(target) == next;
                for (const auto& name : temps_in(dir))
                {
                    std::error_code ec;
                    const auto size = fs::file_size(dir / name, ec);
                    if (!ec && size >= bytes)
                        return true;
                }
                return false;
            };
            const auto guard = std::chrono::steady_clock::now() + kGuard;
            if (at != 0)
                while (!reached() && !child.exited())
                {
                    REQUIRE_MESSAGE(std::chrono::steady_clock::now() < guard,
                                    "save " << i << " neither reached its point nor ended");
                    std::this_thread::sleep_for(std::chrono::microseconds(50));
                }
            ::kill(child.pid(), SIGKILL);
            const Result r = child.wait();
            const auto content = try_read(target);
            const int temps = remove_temps(dir);
            stale += temps;
            if (!content || (*content != current && *content != next))
            {
                if (bad++ == 0)
                    first_bad = "save " + std::to_string(i) + ": target " +
                                (content ? "holds " + std::to_string(content->size()) +
                                               " bytes, hash " + std::to_string(fnv1a(*content))
                                         : std::string("is missing")) +
                                " (old " + std::to_string(current.size()) + " bytes, new " +
                                std::to_string(next.size()) + " bytes)";
                continue;
            }
            if (r.signal != SIGKILL)
                ++finished; // the kill came after the process had exited
            else if (temps > 0)
                ++during; // killed between creating the temporary and renaming it
            else if (*content == next && next != current)
                ++after_rename;
            else
                ++before;
            current = *content;
        }
        MESSAGE("SIGKILL over " << kSaves << " saves (seed " << seed << "): " << before
                                << " before the temporary existed, " << during
                                << " during the write (temporary left), " << after_rename
                                << " after the rename, " << finished << " after exit; " << stale
                                << " stale temporaries removed");
        CHECK_MESSAGE(bad == 0,
                      bad << " kills left a partial or missing target; first: " << first_bad);
        // The test only means something when kills landed in each part of the save.
        CHECK(during > 0);
        CHECK(before > 0);
        CHECK(after_rename + finished > 0);
    }

    TEST_CASE("SIGKILL at every system call of a save (strace): the target is always old or new")
    {
        TracedSave t;
        Scratch& s = t.s;
        const fs::path& dir = t.dir;
        const fs::path& target = t.target;
        const std::string& old = t.old;
        const std::string& next = t.next;
        const auto& args = t.args;
        const std::vector<Syscall>& calls = t.calls;
        REQUIRE(calls.size() > 20);

        int left_old = 0, left_new = 0, stale = 0, bad = 0, missed = 0;
        std::string failures, misses;
        // The first call is the execve that strace starts the tracee with: it cannot be
        // intercepted (and the target is untouched before it anyway).
        REQUIRE(calls.front().name == "execve");
        for (size_t k = 1; k < calls.size(); ++k)
        {
            const Syscall& call = calls[k];
            Result r;
            // A run whose sequence differs from the trace's (a rare extra getrandom) may
            // not reach the injection: try again.
            for (int attempt = 0; attempt < 3 && r.signal != SIGKILL; ++attempt)
            {
                write_bytes(target, old);
                r = run(under_strace("inject=" + call.name +
                                         ":signal=SIGKILL:when=" + std::to_string(call.occurrence),
                                     args),
                        s.logs());
                if (r.signal != SIGKILL)
                    stale += remove_temps(dir);
            }
            const std::string where = "\n  #" + std::to_string(k + 1) + " " + call.line;
            if (r.signal != SIGKILL && missed++ < 5) // the injection must really have hit
                misses += where + ": " + r.describe();
            const auto content = try_read(target);
            stale += remove_temps(dir);
            if (content == old)
                ++left_old;
            else if (content == next)
                ++left_new;
            else if (bad++ < 5)
                failures += where;
        }
        MESSAGE("one save makes " << calls.size() << " system calls; SIGKILL at each (after the "
                                  << "first execve) left the old file " << left_old
                                  << " times, the new one " << left_new << " times; " << stale
                                  << " stale temporaries removed");
        CHECK_MESSAGE(bad == 0, bad << " partial or missing targets, after a kill at:" << failures);
        CHECK_MESSAGE(missed == 0, missed << " runs were not killed:" << misses);
        CHECK(left_old > 0);
        CHECK(left_new > 0);
    }

    TEST_CASE("ENOSPC and EIO at write, fsync, close, rename: exit 3, old file, no temporary")
    {
        TracedSave t;
        Scratch& s = t.s;
        const fs::path& dir = t.dir;
        const fs::path& target = t.target;
        const std::string& old = t.old;
        const std::string& next = t.next;
        const auto& args = t.args;
        const std::vector<Syscall>& calls = t.calls;

        // Find the save in the trace: the temporary's descriptor and what is done with it.
        // Names match by prefix: "rename" is renameat or renameat2 on some architectures.
        const auto find = [&](size_t from, const std::string& name, const std::string& has) {
            for (size_t k = from; k < calls.size(); ++k)
                if (calls[k].name.starts_with(name) && calls[k].line.find(has) != npos)
                    return k;
            return calls.size();
        };
        const std::string quoted = "\"" + target.string() + "\"";
        const size_t first_look = [&] {
            for (size_t k = 0; k < calls.size(); ++k)
                if (calls[k].line.find(quoted) != npos)
                    return k;
            return calls.size();
        }();
        const size_t open_tmp = find(first_look, "openat", ".tmp-");
        REQUIRE_MESSAGE(open_tmp < calls.size(), "no temporary file opened in the trace");
        const std::string& open_line = calls[open_tmp].line;
        const std::string fd = open_line.substr(open_line.rfind("= ") + 2);
        const size_t fchmod = find(open_tmp, "fchmod", "(" + fd + ",");
        const size_t fsync_tmp = find(open_tmp, "fsync", "(" + fd + ")");
        const size_t close_tmp = find(fsync_tmp, "close", "(" + fd + ")");
        const size_t rename = find(close_tmp, "rename", ".tmp-");
        const size_t open_dir = find(rename, "openat", "O_DIRECTORY");
        const size_t fsync_dir = find(open_dir, "fsync", "(");
        std::vector<size_t> writes;
        for (size_t k = open_tmp; k < fsync_tmp; ++k)
            if (calls[k].name == "write" && calls[k].line.find("write(" + fd + ",") != npos)
                writes.push_back(k);
        REQUIRE(fsync_dir < calls.size());
        REQUIRE(!writes.empty());
        MESSAGE("one save: " << calls.size() << " system calls, " << (calls.size() - first_look)
                             << " of them from the first look at the target on, " << writes.size()
                             << " write(s) of " << next.size() << " bytes");

        const auto inject = [&](size_t k, const std::string& what) {
            write_bytes(target, old);
            return run(under_strace("inject=" + calls[k].name + ":" + what +
                                        ":when=" + std::to_string(calls[k].occurrence),
                                    args),
                       s.logs(), {}, std::chrono::seconds(20));
        };
        for (const size_t w : writes)
        {
            check_refused(inject(w, "error=ENOSPC"), target, old,
                          "write failed: No space left on device");
            check_refused(inject(w, "error=EIO"), target, old, "write failed: Input/output error");
            // A write that writes nothing is an error, not a reason to loop or to go on.
            check_refused(inject(w, "retval=0"), target, old, "write failed: Input/output error");
            // An interrupted write is retried and the save succeeds.
            const Result r = inject(w, "error=EINTR");
            CHECK_MESSAGE(r.code == 0, r.describe());
            CHECK(try_read(target) == next);
        }
        for (const char* err : {"EIO", "ENOSPC"})
        {
            CAPTURE(err);
            const std::string text = std::strerror(std::string(err) == "EIO" ? EIO : ENOSPC);
            const std::string e = std::string("error=") + err;
            check_refused(inject(open_tmp, e), target, old,
                          "cannot create a temporary file beside it: " + text);
            check_refused(inject(fchmod, e), target, old, "cannot set permissions: " + text);
            check_refused(inject(fsync_tmp, e), target, old, "cannot flush to disk: " + text);
            check_refused(inject(close_tmp, e), target, old, "close failed: " + text);
            check_refused(inject(rename, e), target, old, "cannot replace the file: " + text);
            // After the rename the new content is in place, and the message says so.
            for (const size_t k : {open_dir, fsync_dir})
            {
                const Result r = inject(k, e);
                INFO(r.describe());
                CHECK(r.code == 3);
                CHECK(r.err.find("'" + target.string() + "': new content is in place") != npos);
                CHECK(r.err.find(text) != npos);
                CHECK(try_read(target) == next);
                CHECK(temps_in(dir).empty());
            }
        }

        // EIO at every system call of the save, from the first look at the target to the
        // directory fsync: a clean failure (exit 3, path and reason named, old file, no
        // temporary) or a complete save. (What follows belongs to the process's exit, and
        // in the sanitizer build to its runtime, not to saving.)
        std::string completed;
        for (size_t k = first_look; k <= fsync_dir; ++k)
        {
            const Result r = inject(k, "error=EIO");
            INFO("EIO at #" << k + 1 << " " << calls[k].line << "\n" << r.describe());
            const auto content = try_read(target);
            CHECK(temps_in(dir).empty());
            if (r.code == 0)
            {
                CHECK(content == next);
                completed += " " + calls[k].name;
                continue;
            }
            CHECK(r.code == 3);
            CHECK(r.err.find("cannot write '" + target.string() + "'") != npos);
            CHECK(r.err.find("Input/output error") != npos);
            CHECK(content == (r.err.find("new content is in place") != npos ? next : old));
        }
        MESSAGE("EIO ignored harmlessly (save completed) at:" << completed);
    }

    TEST_CASE("a full file system (64 KiB tmpfs): exit 3, ENOSPC named, old file, no temporary")
    {
        Scratch s;
        const Meshes m = make_meshes(s);
        const fs::path mnt = s / "mnt";
        fs::create_directories(mnt);
        const fs::path target = mnt / "mesh.obj";
        const std::string old = old_content();
        const NamespaceResult ns = in_private_mount_namespace([&] {
            if (::mount("tmpfs", mnt.c_str(), "tmpfs", 0, "size=64k,mode=0755") != 0)
            {
                write_bytes(s / "mount-error", std::strerror(errno));
                return 125;
            }
            write_bytes(target, old);
            const Result r = run(save_args(m.in_a, target), s.logs());
            write_bytes(s / "result", std::to_string(r.code) + " " + std::to_string(r.signal));
            write_bytes(s / "stderr", r.err);
            write_bytes(s / "after", try_read(target).value_or("<missing>"));
            std::string names;
            for (const auto& name : list_dir(mnt))
                names += name + "\n";
            write_bytes(s / "listing", names);
            return ::umount2(mnt.c_str(), MNT_DETACH) == 0 ? 0 : 124;
        });
        REQUIRE_MESSAGE(ns.entered, "cannot enter a private mount namespace ("
                                        << ns.error
                                        << "): run as root, or allow unprivileged user namespaces");
        REQUIRE_MESSAGE(ns.status != 125, "cannot mount a tmpfs in the private namespace: "
                                              << try_read(s / "mount-error").value_or("?"));
        REQUIRE(ns.status == 0);
        const std::string err = read_bytes(s / "stderr");
        INFO("stderr: " << err);
        CHECK(read_bytes(s / "result") == "3 0");
        CHECK(err.find("meshfair-cli: cannot write '" + target.string() +
                       "': write failed: " + std::strerror(ENOSPC)) != npos);
        CHECK(read_bytes(s / "after") == old);
        CHECK(read_bytes(s / "listing") == "mesh.obj\n");
        CHECK(list_dir(mnt).empty()); // the tmpfs never showed outside its namespace
    }

    TEST_CASE("ulimit -f: exit 3 with EFBIG named, SIGXFSZ ignored by the caller or not")
    {
        Scratch s;
        const Meshes m = make_meshes(s);
        const fs::path target = s / "out" / "mesh.obj";
        fs::create_directories(target.parent_path());
        const std::string old = old_content();
        write_bytes(target, old);

        ChildSetup limited;
        limited.file_size_limit = 64 * 1024;
        limited.ignore_sigxfsz = true;
        // The first write is cut short at the limit, the next one fails with EFBIG.
        check_refused(run(save_args(m.in_a, target), s.logs(), limited), target, old,
                      "write failed: " + std::string(std::strerror(EFBIG)));

        // With SIGXFSZ at its default the kernel would kill a process mid-save (leaving
        // a temporary file); meshfair-cli ignores it itself, so the write fails cleanly.
        limited.ignore_sigxfsz = false;
        check_refused(run(save_args(m.in_a, target), s.logs(), limited), target, old,
                      "write failed: " + std::string(std::strerror(EFBIG)));

        limited.file_size_limit = 4 * 1024 * 1024;
        limited.ignore_sigxfsz = true;
        const Result ok = run(save_args(m.in_a, target), s.logs(), limited);
        CHECK_MESSAGE(ok.code == 0, ok.describe());
        CHECK(try_read(target) == m.out_a);
    }

    TEST_CASE("a read-only directory or target is refused with exit 3 and left as it was")
    {
        Scratch s;
        const Meshes m = make_meshes(s);
        // Root ignores permission bits: the saves run as nobody (65534) when we are root.
        const bool root = ::geteuid() == 0;
        ChildSetup user;
        user.as_nobody = root;
        const auto give_to_nobody = [&](const fs::path& p) {
            if (root)
                REQUIRE(::chown(p.c_str(), 65534, 65534) == 0);
        };
        const fs::path dir = s / "ro";
        fs::create_directories(dir);
        give_to_nobody(dir);
        const fs::path target = dir / "mesh.obj";
        const std::string old = old_content();
        const auto reset = [&](fs::perms mode) {
            write_bytes(target, old);
            give_to_nobody(target);
            fs::permissions(target, mode);
        };

        // Control: with write permission the same save works.
        fs::permissions(dir, fs::perms(0755));
        reset(fs::perms(0644));
        Result r = run(save_args(m.in_a, target), s.logs(), user);
        REQUIRE_MESSAGE(r.code == 0, r.describe());
        CHECK(read_bytes(target) == m.out_a);

        // A read-only directory: no temporary file can be created.
        reset(fs::perms(0644));
        fs::permissions(dir, fs::perms(0555));
        check_refused(run(save_args(m.in_a, target), s.logs(), user), target, old,
                      "cannot create a temporary file beside it: Permission denied");
        fs::permissions(dir, fs::perms(0755));

        // A read-only file in a writable directory: rename would replace it, the policy
        // refuses it (as `>` in a shell would) and keeps its mode.
        reset(fs::perms(0444));
        check_refused(run(save_args(m.in_a, target), s.logs(), user), target, old,
                      "refusing to replace a file you cannot write: Permission denied");
        CHECK(perms_of(target) == "0444");
        if (root)
        {
            // Someone else's file in our directory is not ours to replace either.
            reset(fs::perms(0644));
            REQUIRE(::chown(target.c_str(), 0, 0) == 0);
            check_refused(run(save_args(m.in_a, target), s.logs(), user), target, old,
                          "refusing to replace a file you cannot write: Permission denied");
            // Root may replace a read-only file (as with `>`); the mode is kept.
            reset(fs::perms(0444));
            r = run(save_args(m.in_b, target), s.logs());
            CHECK_MESSAGE(r.code == 0, r.describe());
            CHECK(try_read(target) == m.out_b);
            CHECK(perms_of(target) == "0444");
        }
        else
            MESSAGE("not root: the saves ran as uid " << ::getuid());
    }

    TEST_CASE("a symbolic link is followed: it stays a link and the file it names is replaced")
    {
        Scratch s;
        const Meshes m = make_meshes(s);
        const std::string old = old_content();

        // A relative link in the same directory.
        const fs::path same = s / "same";
        fs::create_directories(same);
        write_bytes(same / "real.obj", old);
        fs::create_symlink("real.obj", same / "link.obj");
        Result r = run(save_args(m.in_a, same / "link.obj"), s.logs());
        REQUIRE_MESSAGE(r.code == 0, r.describe());
        CHECK(fs::is_symlink(same / "link.obj"));
        CHECK(fs::read_symlink(same / "link.obj") == "real.obj");
        CHECK(read_bytes(same / "real.obj") == m.out_a);
        CHECK(list_dir(same) == std::vector<std::string>{"link.obj", "real.obj"});

        // A link into another directory: the temporary is created beside the real file.
        // As nobody, only the real file's directory is writable, so the save can only
        // succeed that way (as root the listings still show where things went).
        const bool root = ::geteuid() == 0;
        const fs::path links = s / "links", data = s / "data";
        fs::create_directories(links);
        fs::create_directories(data);
        write_bytes(data / "real.obj", old);
        fs::create_symlink("../data/real.obj", links / "link.obj");
        ChildSetup user;
        if (root)
        {
            user.as_nobody = true;
            REQUIRE(::chown(data.c_str(), 65534, 65534) == 0);
            REQUIRE(::chown((data / "real.obj").c_str(), 65534, 65534) == 0);
        }
        else
            fs::permissions(links, fs::perms(0555));
        r = run(save_args(m.in_a, links / "link.obj"), s.logs(), user);
        CHECK_MESSAGE(r.code == 0, r.describe());
        CHECK(fs::read_symlink(links / "link.obj") == "../data/real.obj");
        CHECK(read_bytes(data / "real.obj") == m.out_a);
        CHECK(list_dir(links) == std::vector<std::string>{"link.obj"});
        CHECK(list_dir(data) == std::vector<std::string>{"real.obj"});
        fs::permissions(links, fs::perms(0755));

        // A dangling link: the file it names is created (0666 & ~umask).
        const fs::path dangling = s / "dangling";
        fs::create_directories(dangling);
        fs::create_symlink("fresh.obj", dangling / "link.obj");
        ChildSetup umask022;
        umask022.umask = 022;
        r = run(save_args(m.in_b, dangling / "link.obj"), s.logs(), umask022);
        REQUIRE_MESSAGE(r.code == 0, r.describe());
        CHECK(fs::is_symlink(dangling / "link.obj"));
        CHECK(read_bytes(dangling / "fresh.obj") == m.out_b);
        CHECK(perms_of(dangling / "fresh.obj") == "0644");
        CHECK(list_dir(dangling) == std::vector<std::string>{"fresh.obj", "link.obj"});

        // A chain: relative link -> absolute link -> file.
        const fs::path chain = s / "chain";
        fs::create_directories(chain);
        write_bytes(chain / "real.obj", old);
        fs::create_symlink(chain / "real.obj", chain / "abs.obj");
        fs::create_symlink("abs.obj", chain / "rel.obj");
        r = run(save_args(m.in_a, chain / "rel.obj"), s.logs());
        REQUIRE_MESSAGE(r.code == 0, r.describe());
        CHECK(read_bytes(chain / "real.obj") == m.out_a);
        CHECK(fs::is_symlink(chain / "abs.obj"));
        CHECK(fs::is_symlink(chain / "rel.obj"));
        CHECK(list_dir(chain) == std::vector<std::string>{"abs.obj", "real.obj", "rel.obj"});

        // A loop is refused and creates nothing.
        const fs::path loop = s / "loop";
        fs::create_directories(loop);
        fs::create_symlink("b.obj", loop / "a.obj");
        fs::create_symlink("a.obj", loop / "b.obj");
        r = run(save_args(m.in_a, loop / "a.obj"), s.logs());
        INFO(r.describe());
        CHECK(r.code == 3);
        CHECK(r.err.find("'" + (loop / "a.obj").string() +
                         "': cannot follow the symbolic link: " + std::strerror(ELOOP)) != npos);
        CHECK(list_dir(loop) == std::vector<std::string>{"a.obj", "b.obj"});
    }

    TEST_CASE("a directory, a FIFO or a link to a directory is never replaced")
    {
        Scratch s;
        const Meshes m = make_meshes(s);
        const fs::path dir = s / "taken.obj";
        fs::create_directories(dir);
        Result r = run(save_args(m.in_a, dir), s.logs());
        CHECK_MESSAGE(r.code == 3, r.describe());
        CHECK(r.err.find("'" + dir.string() + "': is a directory") != npos);
        CHECK(fs::is_directory(dir));
        CHECK(fs::is_empty(dir));

        fs::create_symlink("taken.obj", s / "link.obj");
        r = run(save_args(m.in_a, s / "link.obj"), s.logs());
        CHECK_MESSAGE(r.code == 3, r.describe());
        CHECK(r.err.find("is a directory") != npos);
        CHECK(fs::is_symlink(s / "link.obj"));

        const fs::path fifo = s / "pipe.obj";
        REQUIRE(::mkfifo(fifo.c_str(), 0644) == 0);
        r = run(save_args(m.in_a, fifo), s.logs());
        CHECK_MESSAGE(r.code == 3, r.describe());
        CHECK(r.err.find("'" + fifo.string() + "': is not a regular file") != npos);
        CHECK(fs::is_fifo(fifo));
        CHECK(temps_in(s.dir()).empty());
    }

    TEST_CASE("a reader polling the target during 200 saves never sees a missing or partial file")
    {
        Scratch s;
        const Meshes m = make_meshes(s);
        const fs::path target = s / "target.obj";
        REQUIRE(run(save_args(m.in_a, target), s.logs()).code == 0);
        const std::uint64_t hash_a = fnv1a(m.out_a), hash_b = fnv1a(m.out_b);

        std::atomic<bool> stop{false};
        long reads = 0, missing = 0, partial = 0;
        std::thread reader([&] {
            while (!stop.load())
            {
                const auto content = try_read(target);
                ++reads;
                if (!content)
                    ++missing;
                else if (const auto h = fnv1a(*content); h != hash_a && h != hash_b)
                    ++partial;
            }
        });
        int failed = 0;
        for (int i = 0; i < 200; ++i)
            failed += run(save_args(i % 2 != 0 ? m.in_b : m.in_a, target), s.logs()).code != 0;
        stop = true;
        reader.join();
        MESSAGE("concurrent reader: " << reads << " whole reads during 200 saves");
        CHECK(failed == 0);
        CHECK(missing == 0);
        CHECK(partial == 0);
        CHECK(reads >= 200);
        CHECK(read_bytes(target) == m.out_b);
    }
}
