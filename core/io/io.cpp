// SPDX-License-Identifier: MIT
// Copyright 2026 the MeshFair authors.
#include "core/io/io.h"

#include <fcntl.h>
#include <sys/stat.h>
#include <unistd.h>

#include <algorithm>
#include <cctype>
#include <cerrno>
#include <cstring>
#include <fstream>
#include <random>

#include "core/errors.h"
#include "core/io/read_obj.h"
#include "core/io/read_off.h"
#include "core/io/read_ply.h"
#include "core/io/read_stl.h"
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
                    ReadReport* report)
{
    ReadReport local;
    ReadReport& r = report ? *report : local;
    r = ReadReport{};
    r.format = format;
    Mesh mesh;
    switch (format)
    {
        case Format::Obj:
            mesh = read_obj(data, name, r);
            break;
        case Format::Off:
            mesh = read_off(data, name, r);
            break;
        case Format::Ply:
            mesh = read_ply(data, name, r);
            break;
        case Format::Stl:
            mesh = read_stl(data, name, r);
            break;
    }
    // Readers validate as they go; this is the invariant every accepted mesh meets.
    validate_mesh(mesh);
    if (mesh.face_count() == 0 && mesh.vertex_count() > 0)
        r.notes.push_back("no faces: read as a point cloud of " +
                          std::to_string(mesh.vertex_count()) + " vertices");
    return mesh;
}

Mesh read_mesh(const std::string& path, ReadReport* report)
{
    const Format format = format_from_path(path);
    const std::string data = read_file(path);
    return read_mesh_data(data, format, path, report);
}

std::string write_mesh_data(const Mesh& mesh, Format format, const WriteOptions& options)
{
    std::string out;
    switch (format)
    {
        case Format::Obj:
            write_obj(mesh, out);
            break;
        case Format::Off:
            write_off(mesh, out);
            break;
        case Format::Ply:
            write_ply(mesh, options.encoding, out);
            break;
        case Format::Stl:
            write_stl(mesh, options.encoding, out);
            break;
    }
    return out;
}

void write_mesh(const Mesh& mesh, const std::string& path, const WriteOptions& options)
{
    const Format format = format_from_path(path);
    write_file_atomically(path, write_mesh_data(mesh, format, options));
}

namespace {

mode_t new_file_mode(const std::string& path)
{
    struct stat st
    {
    };
    if (::stat(path.c_str(), &st) == 0)
        return st.st_mode & 07777;
    // The umask is only readable by changing it; /proc avoids that race.
    mode_t mask = 022;
    std::ifstream status("/proc/self/status");
    std::string key;
    while (status >> key)
        if (key == "Umask:")
        {
            status >> std::oct >> mask;
            break;
        }
    return 0666 & ~mask;
}

} // namespace

void write_file_atomically(const std::string& path, std::string_view data)
{
    const auto fail = [&](const std::string& what, int err) {
        throw WriteError("'" + path + "': " + what + ": " + std::strerror(err));
    };
    struct stat st
    {
    };
    if (::stat(path.c_str(), &st) == 0 && S_ISDIR(st.st_mode))
        throw WriteError("'" + path + "': is a directory");
    std::string tmp = path + ".tmp-XXXXXX";
    const int fd = ::mkstemp(tmp.data());
    if (fd < 0)
        fail("cannot create a temporary file beside it", errno);
    auto abandon = [&](const std::string& what) {
        const int err = errno;
        ::close(fd);
        ::unlink(tmp.c_str());
        fail(what, err);
    };
    const char* p = data.data();
    size_t left = data.size();
    while (left > 0)
    {
        const ssize_t n = ::write(fd, p, left);
        if (n < 0)
        {
            if (errno == EINTR)
                continue;
            abandon("write failed");
        }
        p += n;
        left -= static_cast<size_t>(n);
    }
    if (::fchmod(fd, new_file_mode(path)) != 0)
        abandon("cannot set permissions");
    if (::fsync(fd) != 0)
        abandon("cannot flush to disk");
    if (::close(fd) != 0)
    {
        const int err = errno;
        ::unlink(tmp.c_str());
        fail("close failed", err);
    }
    if (::rename(tmp.c_str(), path.c_str()) != 0)
    {
        const int err = errno;
        ::unlink(tmp.c_str());
        fail("cannot replace the file", err);
    }
}

} // namespace meshfair::io
