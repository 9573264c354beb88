// SPDX-License-Identifier: MIT
// Copyright 2026 the MeshFair authors.
#pragma once

#include <cstdint>
#include <string>
#include <vector>

#include "core/types.h"

namespace meshfair::io {

//! Outcome of normalizing one face read from a file.
struct FaceCheck
{
    bool ok = true;
    std::string problem; //!< why the face is refused, when !ok
    int collapsed = 0;   //!< consecutive repeated indices removed
};

//! \brief Normalizes a face as every reader does: an index repeated at consecutive
//! corners (cyclically, e.g. "5 8 8 1" or "1 2 3 1") is kept once, which exporters
//! write for degenerate polygons. A face left with fewer than 3 vertices, or one
//! that repeats a vertex at non-adjacent corners (a pinched polygon), is refused.
//! `texcoords` and `normals`, when given and not empty, hold one entry per corner of
//! `face` and lose the same corners.
FaceCheck normalize_face(std::vector<Index>& face, std::vector<Index>* texcoords = nullptr,
                         std::vector<Index>* normals = nullptr);

//! Counts one kind of normalization and remembers where it first happened, so a
//! reader reports "collapsed 12 repeated indices in 10 faces (first at line 40)"
//! instead of one note per face.
struct NoteCounter
{
    std::int64_t count = 0;
    std::int64_t elements = 0;
    std::string first_where;
    void add(std::int64_t amount, const std::string& where)
    {
        if (amount <= 0)
            return;
        if (count == 0)
            first_where = where;
        count += amount;
        ++elements;
    }
};

//! Appends "collapsed N consecutive repeated vertex indices in M faces (first at W)".
void report_collapsed(const NoteCounter& counter, std::vector<std::string>& notes);

} // namespace meshfair::io
