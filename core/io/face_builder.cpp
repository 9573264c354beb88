// SPDX-License-Identifier: MIT
// Copyright 2026 the MeshFair authors.
#include "core/io/face_builder.h"

#include "core/mesh/mesh.h"

namespace meshfair::io {

FaceCheck normalize_face(std::vector<Index>& face, std::vector<Index>* texcoords,
                         std::vector<Index>* normals)
{
    FaceCheck check;
    std::vector<Index>* corners[2] = {texcoords, normals};
    for (std::vector<Index>*& c : corners)
        if (c && c->empty())
            c = nullptr;
    size_t kept = 0;
    if (!corners[0] && !corners[1]) // every reader's every face: the plain loop
    {
        for (size_t k = 0; k < face.size(); ++k)
            if (kept == 0 || face[k] != face[kept - 1])
                face[kept++] = face[k];
    }
    else
        for (size_t k = 0; k < face.size(); ++k)
            if (kept == 0 || face[k] != face[kept - 1])
            {
                for (std::vector<Index>* c : corners)
                    if (c)
                        (*c)[kept] = (*c)[k];
                face[kept++] = face[k];
            }
    while (kept > 1 && face[kept - 1] == face[0])
        --kept;
    check.collapsed = static_cast<int>(face.size() - kept);
    face.resize(kept);
    for (std::vector<Index>* c : corners)
        if (c)
            c->resize(kept);
    if (face.size() < 3)
    {
        check.ok = false;
        check.problem = "face has " + std::to_string(face.size()) + " distinct " +
                        (face.size() == 1 ? "vertex" : "vertices") + " (a face needs at least 3)";
        return check;
    }
    if (Index r = repeated_vertex(face); r != kInvalidIndex)
    {
        check.ok = false;
        check.problem =
            "face uses vertex " + std::to_string(r) + " at two corners that are not adjacent";
    }
    return check;
}

void report_collapsed(const NoteCounter& counter, std::vector<std::string>& notes)
{
    if (counter.count == 0)
        return;
    notes.push_back("collapsed " + std::to_string(counter.count) +
                    " consecutive repeated vertex indices in " + std::to_string(counter.elements) +
                    " faces (first at " + counter.first_where + ")");
}

} // namespace meshfair::io
