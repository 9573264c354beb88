// SPDX-License-Identifier: MIT
// Copyright 2026 the MeshFair authors.
#include "core/io/io.h"

#include <fcntl.h>
#include <sys/stat.h>
#include <unistd.h>

#include <algorithm>
#include <cctype>
#include <cerrno>
#include <climits>
#include <cstring>
#include <fstream>

#include "core/errors.h"
#include "core/io/read_obj.h"
#include "core/io/read_off.h"
#include "core/io/read_ply.h"
#include "core/io/read_stl.h"
#include "core/io/text_reader.h"
#include "core/io/write_obj.h"
#include "core/io/write_off.h"
#include "core/io/write_ply.h"
#include "core/io/write_stl.h"

namespace meshfair::io {

Format format_from_path(const std::string& path)
{
    const auto dot = path.find_last_of('.');
    const auto slash = path.find_last_of('/');
    std::string ext;
    if (dot != std::string::npos && (slash == std::string::npos || dot > slash))
        ext = path.substr(dot + 1);
    std::transform(ext.begin(), ext.end(), ext.begin(),
                   [](unsigned char c) { return static_cast<char>(std::tolower(c)); });
    if (ext == "obj")
        return Format::Obj;
    if (ext == "off")
        return Format::Off;
    if (ext == "ply")
        return Format::Ply;
    if (ext == "stl")
        return Format::Stl;
    throw InvalidInputError("'" + path + "': unknown mesh format '." + ext +
                            "' (MeshFair reads and writes .obj, .off, .ply and .stl)");
}

std::string_view format_name(Format format)
{
    switch (format)
    {
        case Format::Obj:
            return "obj";
        case Format::Off:
            return "off";
        case Format::Ply:
            return "ply";
        case Format::Stl:
            return "stl";
    }
    return "?";
}

std::string_view encoding_name(Encoding encoding)
{
    switch (encoding)
    {
        case Encoding::Ascii:
            return "ascii";
        case Encoding::BinaryLittleEndian:
            return "binary_little_endian";
        case Encoding::BinaryBigEndian:
            return "binary_big_endian";
    }
    return "?";
}

std::string read_file(const std::string& path)
{
    struct stat st
    {
    };
    if (::stat(path.c_str(), &st) == 0 && S_ISDIR(st.st_mode))
        throw InvalidInputError("'" + path + "': is a directory, not a mesh file");
    std::ifstream in(path, std::ios::binary);
    if (!in)
        throw InvalidInputError("'" + path + "': cannot open: " + std::strerror(errno));
    std::string data;
    in.seekg(0, std::ios::end);
    const auto size = in.tellg();
    if (size > 0)
    {
        data.resize(static_cast<size_t>(size));
        in.seekg(0, std::ios::beg);
        in.read(data.data(), static_cast<std::streamsize>(data.size()));
        if (in.gcount() != static_cast<std::streamsize>(data.size()))
            throw InvalidInputError("'" + path + "': read failed");
    }
    return data;
}

Mesh read_mesh_data(std::string_view data, Format format, const std::string& name,
                    ReadReport* report, MeshAttributes* attributes)
{
    ReadReport local;
    ReadReport& r = report ? *report : local;
    MeshAttributes local_attributes;
    MeshAttributes& a = attributes ? *attributes : local_attributes;
    a = MeshAttributes{};
    r = ReadReport{};
    r.format = format;
    // A zero-byte file is what a failed download or an interrupted export leaves; no
    // format calls it a mesh. (A well-formed file that declares no vertices is accepted.)
    if (data.empty())
        throw FormatError(SourceLocation::whole(name), "empty file");
    Mesh mesh;
    switch (format)
    {
        case Format::Obj:
            mesh = read_obj(data, name, r, a);
            break;
        case Format::Off:
            mesh = read_off(data, name, r, a);
            break;
        case Format::Ply:
            mesh = read_ply(data, name, r, a);
            break;
        case Format::Stl:
            mesh = read_stl(data, name, r, a);
            break;
    }
    // Readers validate as they go; this is the invariant every accepted mesh meets.
    validate_mesh(mesh);
    if (mesh.face_count() == 0 && mesh.vertex_count() > 0)
        r.notes.push_back("no faces: read as a point cloud of " +
                          count_of(mesh.vertex_count(), "vertex", "vertices"));
    if (mesh.vertex_count() == 0)
        r.notes.push_back("no vertices: the file holds an empty mesh");
    return mesh;
}

Mesh read_mesh(const std::string& path, ReadReport* report, MeshAttributes* attributes)
{
    const Format format = format_from_path(path);
    const std::string data = read_file(path);
    return read_mesh_data(data, format, path, report, attributes);
}

std::string write_mesh_data(const Mesh& mesh, Format format, const WriteOptions& options,
                            const MeshAttributes* attributes, std::vector<std::string>* notes)
{
    const MeshAttributes none;
    const MeshAttributes* a = attributes ? attributes : &none;
    check_attributes(mesh, *a);
    std::vector<std::string> local_notes;
    std::vector<std::string>& n = notes ? *notes : local_notes;
    // Normals of the positions written, unless asked to keep those read.
    MeshAttributes recomputed;
    const bool has_normals = !a->normals.empty() || find_channels(a->vertex).has_normal() ||
                             find_channels(a->face).has_normal();
    if (has_normals && options.normals == Normals::Recompute)
    {
        recomputed = *a;
        recompute_normals(mesh, recomputed);
        a = &recomputed;
    }
    else if (has_normals)
        n.push_back("normals written as read, not recomputed from the positions written");
    std::string out;
    switch (format)
    {
        case Format::Obj:
            write_obj(mesh, *a, out, n);
            break;
        case Format::Off:
            write_off(mesh, *a, out, n);
            break;
        case Format::Ply:
            write_ply(mesh, *a, options.encoding, out, n);
            break;
        case Format::Stl:
            write_stl(mesh, *a, options.encoding, out, n);
            break;
    }
    return out;
}

void write_mesh(const Mesh& mesh, const std::string& path, const WriteOptions& options,
                const MeshAttributes* attributes, std::vector<std::string>* notes)
{
    const Format format = format_from_path(path);
    write_file_atomically(path, write_mesh_data(mesh, format, options, attributes, notes));
}

namespace {

//! The process umask, read from /proc: umask(2) can only read it by changing it, which
//! would race with other threads creating files.
mode_t current_umask()
{
    mode_t mask = 022;
    std::ifstream status("/proc/self/status");
    std::string key;
    while (status >> key)
        if (key == "Umask:")
        {
            status >> std::oct >> mask;
            break;
        }
    return mask;
}

//! The directory part of `path` with its trailing slash ("a/b" -> "a/"), "" for a bare name.
std::string directory_of(const std::string& path)
{
    const auto slash = path.find_last_of('/');
    return slash == std::string::npos ? std::string() : path.substr(0, slash + 1);
}

[[noreturn]] void throw_write_error(const std::string& name, const std::string& step, int err)
{
    throw WriteError(name + ": " + step + ": " + std::strerror(err));
}

} // namespace

void write_file_atomically(const std::string& path, std::string_view data)
{
    // Follow symbolic links (at most 40, like the kernel) to the file to replace: the link
    // stays a link and the temporary file is created beside the real file. A dangling
    // link names the file to create, relative to the link's own directory.
    std::string target = path;
    struct stat st
    {
    };
    bool exists = false;
    for (int hops = 0;; ++hops)
    {
        if (::lstat(target.c_str(), &st) != 0)
        {
            if (errno != ENOENT)
                throw_write_error("'" + path + "'", "cannot examine it", errno);
            break;
        }
        exists = !S_ISLNK(st.st_mode);
        if (exists)
            break;
        if (hops == 40)
            throw_write_error("'" + path + "'", "cannot follow the symbolic link", ELOOP);
        char link[PATH_MAX];
        const ssize_t n = ::readlink(target.c_str(), link, sizeof link);
        if (n < 0 || n == static_cast<ssize_t>(sizeof link)) // a full buffer may be cut short
            throw_write_error("'" + path + "'", "cannot follow the symbolic link",
                              n < 0 ? errno : ENAMETOOLONG);
        const std::string next(link, static_cast<size_t>(n));
        target = next.starts_with('/') ? next : directory_of(target) + next;
    }
    const std::string name = "'" + path + "'" + (target == path ? "" : " (-> '" + target + "')");

    // Only a regular file the caller could open for writing is replaced (rename would also
    // replace a read-only file, a device or a FIFO: that would surprise the user).
    if (exists && S_ISDIR(st.st_mode))
        throw WriteError(name + ": is a directory");
    if (exists && !S_ISREG(st.st_mode))
        throw WriteError(name + ": is not a regular file (only regular files are replaced)");
    if (exists && ::faccessat(AT_FDCWD, target.c_str(), W_OK, AT_EACCESS) != 0)
        throw_write_error(name, "refusing to replace a file you cannot write", errno);
    const mode_t mode = exists ? st.st_mode & 07777 : 0666 & ~current_umask();

    // The temporary file: in the same directory (so the rename is atomic), O_EXCL, O_CLOEXEC.
    std::string tmp = target + ".tmp-XXXXXX";
    const int fd = ::mkostemp(tmp.data(), O_CLOEXEC);
    if (fd < 0)
        throw_write_error(name, "cannot create a temporary file beside it", errno);
    bool fd_open = true;
    // On failure the temporary is closed and removed (best effort: it is being discarded,
    // so these results change nothing) and the target is never touched.
    const auto abandon = [&](const std::string& step, int err) {
        if (fd_open)
            ::close(fd);
        ::unlink(tmp.c_str());
        throw_write_error(name, step, err);
    };
    if (::fchmod(fd, mode) != 0)
        abandon("cannot set permissions", errno);
    for (size_t done = 0; done < data.size();)
    {
        const ssize_t n = ::write(fd, data.data() + done, data.size() - done);
        if (n < 0 && errno == EINTR)
            continue;
        if (n <= 0) // 0 bytes for a non-empty request: an error, never a reason to spin
            abandon("write failed", n < 0 ? errno : EIO);
        done += static_cast<size_t>(n); // a short write goes on with the rest
    }
    // Never retried: after a failed fsync the kernel may have dropped the dirty pages, and
    // a second fsync could report success for data that is lost.
    if (::fsync(fd) != 0)
        abandon("cannot flush to disk", errno);
    fd_open = false; // Linux releases the descriptor even when close fails
    if (::close(fd) != 0)
        abandon("close failed", errno);
    if (::rename(tmp.c_str(), target.c_str()) != 0)
        abandon("cannot replace the file", errno);

    // Make the rename durable. The new content is in place from here on.
    const std::string dir = directory_of(target).empty() ? "." : directory_of(target);
    const int dir_fd = ::open(dir.c_str(), O_RDONLY | O_DIRECTORY | O_CLOEXEC);
    if (dir_fd < 0)
        throw_write_error(name, "new content is in place, but its directory cannot be opened",
                          errno);
    const int sync_error = ::fsync(dir_fd) != 0 ? errno : 0;
    const int close_error = ::close(dir_fd) != 0 ? errno : 0;
    if (sync_error != 0 || close_error != 0)
        throw_write_error(name, "new content is in place, but flushing its directory failed",
                          sync_error != 0 ? sync_error : close_error);
}

} // namespace meshfair::io
