// SPDX-License-Identifier: MIT
// Copyright 2026 the MeshFair authors.
#include "app/bench/fair_case.h"

#include <algorithm>
#include <numeric>
#include <stdexcept>

#include "core/geometry/face_geometry.h"

namespace meshfair::bench {

std::vector<Index> FairCase::free_vertices() const
{
    std::vector<Index> pinned = pins;
    std::sort(pinned.begin(), pinned.end());
    std::vector<Index> out;
    out.reserve(region.size());
    std::set_difference(region.begin(), region.end(), pinned.begin(), pinned.end(),
                        std::back_inserter(out));
    return out;
}

std::vector<Scalar> FairCase::flat(const std::vector<Vec3>& targets)
{
    std::vector<Scalar> out;
    out.reserve(3 * targets.size());
    for (const Vec3& t : targets)
        out.insert(out.end(), t.begin(), t.end());
    return out;
}

FairCase make_fair_case(const Mesh& mesh, Index pin_candidates, const FairCaseShape& shape)
{
    const Index n = mesh.vertex_count();
    if (shape.pins < 1 || pin_candidates < shape.pins || pin_candidates > n)
        throw std::invalid_argument("make_fair_case: fewer candidate vertices than pins");
    const int up = shape.up_axis;
    const BoundingBox box = bounding_box(mesh.positions);
    FairCase out;
    out.diagonal = box.diagonal();
    const Scalar floor = box.min[up] + shape.fixed_bottom * (box.max[up] - box.min[up]);
    for (Index i = 0; i < n; ++i)
        if (mesh.positions[3 * static_cast<size_t>(i) + up] > floor)
            out.region.push_back(i);

    // The highest candidates; ties by index, so the choice never depends on the sort.
    std::vector<Index> candidates(static_cast<size_t>(pin_candidates));
    std::iota(candidates.begin(), candidates.end(), 0);
    const auto height = [&](Index i) { return mesh.positions[3 * static_cast<size_t>(i) + up]; };
    std::partial_sort(
        candidates.begin(), candidates.begin() + shape.pins, candidates.end(),
        [&](Index a, Index b) { return height(a) != height(b) ? height(a) > height(b) : a < b; });
    out.pins.assign(candidates.begin(), candidates.begin() + shape.pins);
    for (const Index p : out.pins)
    {
        if (!std::binary_search(out.region.begin(), out.region.end(), p))
            throw std::invalid_argument("make_fair_case: a pin lies in the fixed strip");
        Vec3 first = mesh.position(p), second = first;
        first[up] += shape.first_lift * out.diagonal;
        second[up] += shape.second_lift * out.diagonal;
        out.first_targets.push_back(first);
        out.second_targets.push_back(second);
    }
    return out;
}

Recipe fair_recipe(const FairCase& fair_case, const std::vector<Vec3>& targets, Method method)
{
    Recipe r;
    r.method = method;
    r.region = Region{fair_case.region, {}};
    r.hard = HardVertices{fair_case.pins, targets};
    return r;
}

} // namespace meshfair::bench
