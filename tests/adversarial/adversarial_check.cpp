// SPDX-License-Identifier: MIT
// Copyright 2026 the MeshFair authors.
//
// Runs meshfair-cli on every file of tests/adversarial/ and checks it against
// expected.tsv: the exit code, and the first line on stderr for a refused file or the
// content hash of the normalized mesh for an accepted one. Every run happens in a child
// process under a memory limit and a CPU-time limit (a hang guard: it only ever fails);
// its peak memory must stay within 64 MiB + 8 x the file's size. Accepted files are also smoothed
// (the invariants are checked after smoothing), written back in their own format and re-read, which
// must give the identical mesh.
//
//   adversarial_check CLI DIR            check, exit 1 on any difference
//   adversarial_check CLI DIR --record   print a fresh expected.tsv (review it by hand)
#include <fcntl.h>
#include <signal.h>
#include <sys/resource.h>
#include <sys/wait.h>
#include <unistd.h>

#include <algorithm>
#include <cerrno>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <iostream>
#include <map>
#include <sstream>
#include <string>
#include <vector>

namespace fs = std::filesystem;

namespace {

#if defined(__SANITIZE_ADDRESS__)
constexpr bool kSanitized = true;
#elif defined(__has_feature)
#if __has_feature(address_sanitizer)
constexpr bool kSanitized = true;
#else
constexpr bool kSanitized = false;
#endif
#else
constexpr bool kSanitized = false;
#endif

constexpr long kMiB = 1024 * 1024;
// Address space granted to a child. ASan reserves terabytes of shadow address space,
// so a sanitized build is limited by the peak-RSS check alone.
constexpr rlim_t kAddressLimit = 1024 * kMiB;
constexpr unsigned kTimeLimitSeconds = 20;

struct Run
{
    int code = -1;   // exit code, or 128 + signal
    std::string out; // stdout
    std::string err; // stderr
    long max_rss_kib = 0;
    double cpu_seconds = 0; // user + system: the work done, whatever else the machine runs
};

std::string slurp(const fs::path& path)
{
    std::ifstream in(path, std::ios::binary);
    std::ostringstream s;
    s << in.rdbuf();
    return s.str();
}

// Runs argv in `cwd` with stdout and stderr captured in files, under the limits. The
// child's peak RSS (ru_maxrss) includes what it shared with this process between fork
// and exec, so this process keeps nothing large while it runs a child.
Run run(const std::vector<std::string>& argv, const fs::path& cwd, const fs::path& scratch)
{
    const fs::path out = scratch / "stdout", err = scratch / "stderr";
    const pid_t pid = ::fork();
    if (pid < 0)
    {
        std::perror("fork");
        std::exit(1);
    }
    if (pid == 0)
    {
        const int o = ::open(out.c_str(), O_WRONLY | O_CREAT | O_TRUNC, 0644);
        const int e = ::open(err.c_str(), O_WRONLY | O_CREAT | O_TRUNC, 0644);
        if (o < 0 || e < 0 || ::dup2(o, 1) < 0 || ::dup2(e, 2) < 0 || ::chdir(cwd.c_str()) != 0)
            ::_exit(126);
        if (!kSanitized)
        {
            const rlimit as{kAddressLimit, kAddressLimit};
            ::setrlimit(RLIMIT_AS, &as);
        }
        const rlimit cpu{kTimeLimitSeconds, kTimeLimitSeconds};
        ::setrlimit(RLIMIT_CPU, &cpu);
        ::alarm(kTimeLimitSeconds); // wall clock too: a hang blocked on I/O still ends
        std::vector<char*> args;
        for (const std::string& a : argv)
            args.push_back(const_cast<char*>(a.c_str()));
        args.push_back(nullptr);
        ::execv(args[0], args.data());
        ::_exit(127);
    }
    int status = 0;
    rusage usage{};
    while (::wait4(pid, &status, 0, &usage) < 0)
        if (errno != EINTR)
        {
            std::perror("wait4");
            std::exit(1);
        }
    Run r;
    r.code = WIFEXITED(status) ? WEXITSTATUS(status) : 128 + WTERMSIG(status);
    r.out = slurp(out);
    r.err = slurp(err);
    r.max_rss_kib = usage.ru_maxrss;
    r.cpu_seconds = static_cast<double>(usage.ru_utime.tv_sec + usage.ru_stime.tv_sec) +
                    1e-6 * static_cast<double>(usage.ru_utime.tv_usec + usage.ru_stime.tv_usec);
    return r;
}

std::string first_line(const std::string& text)
{
    return text.substr(0, text.find('\n'));
}

// The "content_hash: ..." value printed by `meshfair-cli info`.
std::string content_hash(const std::string& info)
{
    const std::string key = "content_hash:";
    const auto at = info.find(key);
    if (at == std::string::npos)
        return "";
    std::istringstream rest(info.substr(at + key.size()));
    std::string hash;
    rest >> hash;
    return hash;
}

struct Expected
{
    int code = 0;
    std::string outcome; // "hash:<hex>" or the first line on stderr
};

std::map<std::string, Expected> read_expected(const fs::path& path)
{
    std::map<std::string, Expected> cases;
    std::ifstream in(path);
    std::string line;
    int number = 0;
    while (std::getline(in, line))
    {
        ++number;
        if (line.empty() || line[0] == '#')
            continue;
        const auto a = line.find('\t');
        const auto b = a == std::string::npos ? a : line.find('\t', a + 1);
        if (b == std::string::npos)
        {
            std::cerr << path.string() << ":" << number << ": expected FILE<TAB>CODE<TAB>OUTCOME\n";
            std::exit(1);
        }
        cases[line.substr(0, a)] = {std::atoi(line.substr(a + 1, b - a - 1).c_str()),
                                    line.substr(b + 1)};
    }
    return cases;
}

bool is_recipe(const std::string& file)
{
    return file.starts_with("recipe/") && file.ends_with(".json");
}

// ---- generated inputs: size-scaled pathological shapes ---------------------------------
//
// Each shape repeats one pattern up to a target size. Read at 1 and 4 MiB, the work (the
// child's CPU time, which another process on the machine does not lengthen) must grow no
// faster than linearly (ratio <= 8 where linear gives 4 and quadratic 16), and memory
// must stay in bounds. How fast a reader is belongs to the benchmarks.

struct Shape
{
    std::string name; // file name, its extension picks the reader
    std::string (*make)(size_t bytes);
};

std::string repeat_to(std::string head, const std::string& unit, size_t bytes,
                      const std::string& tail = "")
{
    while (head.size() + unit.size() + tail.size() <= bytes)
        head += unit;
    return head + tail;
}

std::string numbered_vertices(size_t count, const char* prefix = "v ")
{
    std::string s;
    for (size_t i = 0; i < count; ++i)
        s += prefix + std::to_string(i % 1000) + " " + std::to_string(i / 1000) + " 0\n";
    return s;
}

std::string index_list(size_t count, size_t base)
{
    std::string s;
    for (size_t i = 0; i < count; ++i)
        s += " " + std::to_string(i + base);
    return s;
}

std::string ply_ascii_header(size_t vertices, size_t faces)
{
    return "ply\nformat ascii 1.0\nelement vertex " + std::to_string(vertices) +
           "\nproperty double x\nproperty double y\nproperty double z\nelement face " +
           std::to_string(faces) + "\nproperty list uint int vertex_indices\nend_header\n";
}

const Shape kShapes[] = {
    {"obj_many_vertices.obj", [](size_t b) { return repeat_to("", "v 0.125 1.5 -2.75\n", b); }},
    {"obj_many_triangles.obj",
     [](size_t b) { return repeat_to("v 0 0 0\nv 1 0 0\nv 0 1 0\n", "f 1 2 3\n", b); }},
    {"obj_one_long_face.obj",
     [](size_t b) {
         const size_t n = b / 20;
         return numbered_vertices(n) + "f" + index_list(n, 1) + "\n";
     }},
    {"obj_long_vertex_line.obj", [](size_t b) { return repeat_to("v 1 2 3", " 4", b, "\n"); }},
    {"obj_long_comment.obj",
     [](size_t b) { return repeat_to("#", "x", b, "\nv 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 3\n"); }},
    {"obj_many_unknown_lines.obj", [](size_t b) { return repeat_to("", "zz 1\n", b); }},
    {"off_many_vertices.off",
     [](size_t b) {
         const size_t n = b / 16;
         return "OFF\n" + std::to_string(n) + " 0 0\n" + numbered_vertices(n, "");
     }},
    {"off_one_long_face.off",
     [](size_t b) {
         const size_t n = b / 20;
         return "OFF\n" + std::to_string(n) + " 1 0\n" + numbered_vertices(n, "") +
                std::to_string(n) + index_list(n, 0) + "\n";
     }},
    {"off_long_line.off", [](size_t b) { return repeat_to("OFF\n1 0 0\n0 0 0", " 0", b, "\n"); }},
    {"ply_ascii_many_faces.ply",
     [](size_t b) {
         const size_t n = b / 8;
         return ply_ascii_header(3, n) + "0 0 0\n1 0 0\n0 1 0\n" +
                repeat_to("", "3 0 1 2\n", n * 8);
     }},
    {"ply_ascii_one_long_face.ply",
     [](size_t b) {
         const size_t n = b / 20;
         return ply_ascii_header(n, 1) + numbered_vertices(n, "") + std::to_string(n) +
                index_list(n, 0) + "\n";
     }},
    {"ply_many_properties.ply",
     [](size_t b) {
         std::string s = "ply\nformat ascii 1.0\nelement vertex 1\n";
         size_t n = 0;
         while (s.size() + 40 < b * 3 / 4)
             s += "property float p" + std::to_string(n++) + "\n";
         s += "property float x\nproperty float y\nproperty float z\nend_header\n";
         for (size_t k = 0; k < n + 3; ++k)
             s += "0 ";
         return s + "\n";
     }},
    {"ply_many_elements.ply",
     [](size_t b) {
         std::string s = "ply\nformat ascii 1.0\n";
         for (size_t n = 0; s.size() + 80 < b; ++n)
             s += "element e" + std::to_string(n) + " 0\n";
         return s +
                "element vertex 0\nproperty float x\nproperty float y\nproperty float z\n"
                "end_header\n";
     }},
    {"ply_binary_long_lists.ply",
     [](size_t b) {
         const size_t n = b / 1021;
         std::string s =
             "ply\nformat binary_little_endian 1.0\nelement vertex 255\n"
             "property float x\nproperty float y\nproperty float z\nelement face " +
             std::to_string(n) + "\nproperty list uchar int vertex_indices\nend_header\n";
         for (int i = 0; i < 255; ++i)
         {
             const float p[3] = {static_cast<float>(i), static_cast<float>(i * i % 7), 0};
             s.append(reinterpret_cast<const char*>(p), sizeof p);
         }
         std::string face(1, static_cast<char>(255));
         for (std::int32_t i = 0; i < 255; ++i)
             face.append(reinterpret_cast<const char*>(&i), 4);
         for (size_t f = 0; f < n; ++f)
             s += face;
         return s;
     }},
    {"stl_ascii_many_facets.stl",
     [](size_t b) {
         std::string s = "solid big\n";
         for (size_t k = 0; s.size() + 200 < b; ++k)
         {
             const std::string x = std::to_string(k);
             s += "facet normal 0 0 1\nouter loop\nvertex " + x + " 0 0\nvertex " + x +
                  " 1 0\nvertex " + x + " 0 1\nendloop\nendfacet\n";
         }
         return s + "endsolid big\n";
     }},
    {"stl_ascii_long_name.stl",
     [](size_t b) {
         return repeat_to("solid ", "n", b - 120,
                          "\nfacet normal 0 0 1\nouter loop\nvertex 0 0 0\nvertex 1 0 0\n"
                          "vertex 0 1 0\nendloop\nendfacet\nendsolid\n");
     }},
    {"stl_binary_many_triangles.stl",
     [](size_t b) {
         const std::uint32_t n = static_cast<std::uint32_t>((b - 84) / 50);
         std::string s(80, '\0');
         s.append(reinterpret_cast<const char*>(&n), 4);
         for (std::uint32_t t = 0; t < n; ++t)
         {
             const float v[12] = {0,
                                  0,
                                  1,
                                  static_cast<float>(t),
                                  0,
                                  0,
                                  static_cast<float>(t),
                                  1,
                                  0,
                                  static_cast<float>(t),
                                  0,
                                  1};
             s.append(reinterpret_cast<const char*>(v), sizeof v);
             s.append(2, '\0');
         }
         return s;
     }},
};

// The CPU time of a run: the median of three.
double seconds_of(const std::vector<std::string>& argv, const fs::path& cwd,
                  const fs::path& scratch, Run* last)
{
    std::vector<double> times;
    for (int k = 0; k < 3; ++k)
    {
        *last = run(argv, cwd, scratch);
        times.push_back(last->cpu_seconds);
    }
    std::sort(times.begin(), times.end());
    return times[1]; // the median of three
}

} // namespace

int main(int argc, char** argv)
{
    if (argc < 3)
    {
        std::cerr << "usage: adversarial_check CLI DIR [--record]\n";
        return 2;
    }
    const std::string cli = fs::absolute(argv[1]).string();
    const fs::path dir = fs::absolute(argv[2]);
    const bool record = argc > 3 && std::string(argv[3]) == "--record";
    const fs::path scratch =
        fs::temp_directory_path() / ("meshfair-adversarial-" + std::to_string(::getpid()));
    fs::create_directories(scratch);

    std::vector<std::string> files;
    for (const auto& entry : fs::recursive_directory_iterator(dir))
    {
        const std::string rel = fs::relative(entry.path(), dir).generic_string();
        const std::string ext = entry.path().extension().string();
        if (entry.is_regular_file() && rel.find('/') != std::string::npos &&
            (ext == ".obj" || ext == ".off" || ext == ".ply" || ext == ".stl" || ext == ".json") &&
            rel != "recipe/square.obj")
            files.push_back(rel);
    }
    std::sort(files.begin(), files.end());
    const auto expected =
        record ? std::map<std::string, Expected>{} : read_expected(dir / "expected.tsv");

    int failures = 0, accepted = 0, refused = 0;
    long worst_rss_kib = 0;
    std::string worst_rss_file;
    auto fail = [&](const std::string& file, const std::string& what) {
        ++failures;
        std::cout << "FAIL " << file << ": " << what << "\n";
    };
    if (record)
        std::cout << "# file\texit code\tfirst line on stderr, or hash:<content hash> when "
                     "accepted\n";
    for (const std::string& file : files)
    {
        const auto size = static_cast<long>(fs::file_size(dir / file));
        const fs::path out = scratch / ("out" + fs::path(file).extension().string());
        Run r = is_recipe(file) ? run({cli, "smooth", "recipe/square.obj", "--recipe", file, "-o",
                                       (scratch / "out.obj").string(), "-q"},
                                      dir, scratch)
                                : run({cli, "info", file}, dir, scratch);
        const std::string outcome =
            r.code == 0 ? (is_recipe(file) ? "smoothed" : "hash:" + content_hash(r.out))
                        : first_line(r.err);
        if (r.code != 0 && r.code != 2)
            fail(file, "exit code " + std::to_string(r.code) + " (a crash, a hang or an internal " +
                           "error): " + first_line(r.err));
        const long limit_kib = (64 * kMiB + 8 * size) / 1024;
        if (r.max_rss_kib > limit_kib)
            fail(file, "peak memory " + std::to_string(r.max_rss_kib) + " KiB exceeds " +
                           std::to_string(limit_kib) + " KiB");
        if (r.max_rss_kib > worst_rss_kib)
        {
            worst_rss_kib = r.max_rss_kib;
            worst_rss_file = file;
        }
        if (record)
        {
            std::cout << file << "\t" << r.code << "\t" << outcome << "\n";
            continue;
        }
        const auto e = expected.find(file);
        if (e == expected.end())
        {
            fail(file, "not listed in expected.tsv");
            continue;
        }
        if (e->second.code != r.code || e->second.outcome != outcome)
            fail(file, "expected exit " + std::to_string(e->second.code) + " and\n    " +
                           e->second.outcome + "\n  got exit " + std::to_string(r.code) +
                           " and\n    " + outcome);
        if (r.code != 0)
        {
            ++refused;
            continue;
        }
        ++accepted;
        if (is_recipe(file))
            continue;
        // Smoothing keeps the invariants (the CLI checks them before writing); its own
        // output, written in the same format and read again, is the identical mesh.
        const Run smoothed = run({cli, "smooth", file, "-o", out.string(), "-q"}, dir, scratch);
        // Smoothing may refuse what it cannot solve (coordinates beyond 1e100), naming the
        // file; anything else is a failure.
        if (smoothed.code != 0 &&
            !(smoothed.code == 2 && first_line(smoothed.err).find(file) != std::string::npos))
            fail(file, "smoothing an accepted file failed: " + first_line(smoothed.err));
        // STL stores triangles only, so a polygon comes back fan-triangulated: there the
        // mesh written must come back identical from its own output.
        std::string written = content_hash(r.out);
        const bool stl = out.extension() == ".stl";
        for (int round = 0; round < (stl ? 2 : 1); ++round)
        {
            const std::string source = round == 0 ? file : out.string();
            const fs::path target = scratch / ("again" + out.extension().string());
            const Run copied = run({cli, "convert", source, "-o", target.string()}, dir, scratch);
            const Run reread = run({cli, "info", target.string()}, dir, scratch);
            const std::string hash = content_hash(reread.out);
            if (copied.code != 0)
            {
                fail(file, "writing it again failed: " + first_line(copied.err));
                break;
            }
            fs::rename(target, out);
            if (copied.code == 0 && reread.code == 0 && hash == written)
                break;
            if (round == 0 && stl && copied.code == 0 && reread.code == 0)
            {
                written = hash; // triangulated: check that this one round-trips
                continue;
            }
            fail(file, "re-reading MeshFair's own output gives another mesh (" + hash +
                           " instead of " + written + ")");
        }
    }
    // Size-scaled shapes: linear growth from 1 to 4 MiB, memory bound.
    if (!record)
        for (const Shape& shape : kShapes)
        {
            double seconds[2] = {0, 0};
            for (int k = 0; k < 2; ++k)
            {
                const size_t bytes = (k == 0 ? 1 : 4) * static_cast<size_t>(kMiB);
                const fs::path path = scratch / shape.name;
                {
                    std::ofstream file(path, std::ios::binary);
                    const std::string data = shape.make(bytes);
                    file.write(data.data(), static_cast<std::streamsize>(data.size()));
                }
                const auto size = static_cast<long>(fs::file_size(path));
                Run r;
                seconds[k] = seconds_of({cli, "info", path.string()}, scratch, scratch, &r);
                if (r.code != 0 && r.code != 2)
                    fail(shape.name,
                         "exit code " + std::to_string(r.code) + ": " + first_line(r.err));
                // ASan's shadow memory and quarantine grow with what a run allocates, so
                // at megabytes the bound speaks of the release build, checked there.
                const long limit_kib = (64 * kMiB + 8 * size) / 1024;
                if (!kSanitized && r.max_rss_kib > limit_kib)
                    fail(shape.name, std::to_string(size) + " bytes: peak memory " +
                                         std::to_string(r.max_rss_kib) + " KiB exceeds " +
                                         std::to_string(limit_kib) + " KiB");
                if (k == 1)
                    std::cout << "  " << shape.name << ": "
                              << (r.code == 0 ? "accepted" : "refused") << ", 1 MiB in "
                              << static_cast<int>(seconds[0] * 1000) << " ms of CPU, 4 MiB in "
                              << static_cast<int>(seconds[1] * 1000) << " ms, peak "
                              << r.max_rss_kib / 1024 << " MiB\n";
                fs::remove(path);
            }
            // Process start-up is in both times, so a linear reader shows a ratio under 4.
            // A ratio over 8 is measured twice more, each size keeping its least: caches
            // shared with another process can lengthen one run, a superlinear reader is
            // slow every time.
            for (int retry = 0; retry < 2 && seconds[1] > 8 * seconds[0] && seconds[1] > 0.05;
                 ++retry)
                for (int k = 0; k < 2; ++k)
                {
                    const fs::path path = scratch / shape.name;
                    {
                        std::ofstream file(path, std::ios::binary);
                        const std::string data = shape.make((k == 0 ? 1 : 4) * kMiB);
                        file.write(data.data(), static_cast<std::streamsize>(data.size()));
                    }
                    Run r;
                    seconds[k] = std::min(
                        seconds[k], seconds_of({cli, "info", path.string()}, scratch, scratch, &r));
                    fs::remove(path);
                }
            if (seconds[1] > 8 * seconds[0] && seconds[1] > 0.05)
                fail(shape.name, "work grows faster than linearly: 1 MiB in " +
                                     std::to_string(seconds[0]) + " s of CPU, 4 MiB in " +
                                     std::to_string(seconds[1]) + " s");
        }

    for (const auto& [file, e] : expected)
        if (std::find(files.begin(), files.end(), file) == files.end())
            fail(file, "listed in expected.tsv but missing");
    fs::remove_all(scratch);
    if (record)
        return 0;
    std::cout << files.size() << " files: " << refused << " refused, " << accepted << " accepted, "
              << failures << " failures; peak memory at most " << worst_rss_kib << " KiB ("
              << worst_rss_file << ")\n";
    return failures == 0 ? 0 : 1;
}
