// SPDX-License-Identifier: MIT
// Copyright 2026 the MeshFair authors.
#include "app/edit/constraint_sets.h"

#include <algorithm>
#include <tuple>
#include <utility>

#include "app/render/palette.h"
#include "core/geometry/face_geometry.h"
#include "core/select/mesh_select.h"

namespace meshfair::app {

namespace {

std::string quoted(const ConstraintSet& s)
{
    return "'" + s.name + "'";
}

// The elements of every enabled set of `kind`, in set order, each once (the first set keeps
// it), without those a winning kind's sets hold; `from` says which set each came from.
std::vector<Index> merged(const std::vector<ConstraintSet>& sets, ConstraintKind kind,
                          bool vertices, std::vector<const ConstraintSet*>* from = nullptr,
                          std::vector<size_t>* position = nullptr)
{
    std::vector<Index> out;
    const std::optional<ConstraintKind> winner = kind_info(kind).loses_to;
    const auto counted = [&](const ConstraintSet& s) {
        return s.enabled && (s.kind == kind || (winner && s.kind == *winner));
    };
    // Flags over the elements' range, not a hash set: a preset's sets of every face (100k
    // of them on a scan) are merged at each restart, a smoothing-brush dab's too.
    bool any = false;
    Index lo = 0, hi = 0;
    for (const ConstraintSet& s : sets)
        if (counted(s))
            for (const Index e : vertices ? s.vertices : s.faces)
            {
                lo = any ? std::min(lo, e) : e;
                hi = any ? std::max(hi, e) : e;
                any = true;
            }
    if (!any)
        return out;
    std::vector<char> seen(static_cast<size_t>(hi - lo) + 1, 0);
    const auto first_time = [&](Index e) {
        char& flag = seen[static_cast<size_t>(e - lo)];
        return !std::exchange(flag, char(1));
    };
    if (winner)
        for (const ConstraintSet& s : sets)
            if (s.kind == *winner && s.enabled)
                for (const Index e : vertices ? s.vertices : s.faces)
                    (void)first_time(e);
    for (const ConstraintSet& s : sets)
    {
        if (s.kind != kind || !s.enabled)
            continue;
        const std::vector<Index>& list = vertices ? s.vertices : s.faces;
        for (size_t k = 0; k < list.size(); ++k)
            if (first_time(list[k]))
            {
                out.push_back(list[k]);
                if (from)
                    from->push_back(&s);
                if (position)
                    position->push_back(k);
            }
    }
    return out;
}

bool any_of_kind(const std::vector<ConstraintSet>& sets, ConstraintKind kind)
{
    return std::any_of(sets.begin(), sets.end(), [&](const ConstraintSet& s) {
        return s.kind == kind && s.enabled && !(s.vertices.empty() && s.faces.empty());
    });
}

// Each merged element's weight: its set's weight times its value of the set's weight map.
std::vector<Scalar> element_weights(const std::vector<const ConstraintSet*>& from,
                                    const std::vector<size_t>& at, const SolverSettings& settings)
{
    std::vector<Scalar> each(from.size());
    for (size_t k = 0; k < from.size(); ++k)
        each[k] = from[k]->weights.empty()
                      ? weight_of(*from[k], settings)
                      : weight_of(*from[k], settings) * from[k]->weights[at[k]];
    return each;
}

// A section's weights from its elements': one mu when all are the same (as one weight, bit
// for bit), else mu = 1 and one weight per element.
void collapse(std::vector<Scalar> each, Scalar& mu, std::vector<Scalar>& weights)
{
    if (each.empty())
        return;
    if (std::all_of(each.begin(), each.end(), [&](Scalar w) { return w == each.front(); }))
    {
        mu = each.front();
        weights.clear();
        return;
    }
    mu = 1;
    weights = std::move(each);
}

void weigh(const std::vector<const ConstraintSet*>& from, const std::vector<size_t>& at,
           const SolverSettings& settings, Scalar& mu, std::vector<Scalar>& weights)
{
    collapse(element_weights(from, at, settings), mu, weights);
}

std::vector<Index> sorted(std::vector<Index> v)
{
    std::sort(v.begin(), v.end());
    v.erase(std::unique(v.begin(), v.end()), v.end());
    return v;
}

Vec3 position(std::span<const Scalar> positions, Index v)
{
    const size_t k = 3 * static_cast<size_t>(v);
    return {positions[k], positions[k + 1], positions[k + 2]};
}

// Per-face normals of the merged faces of `kind` when a set gives its own: the set's, else
// `fallback(f)`; empty when no set gives any.
template <class Fallback>
std::vector<Vec3> merged_normals(const std::vector<ConstraintSet>& sets, ConstraintKind kind,
                                 Fallback fallback)
{
    std::vector<const ConstraintSet*> from;
    std::vector<size_t> at;
    const std::vector<Index> faces = merged(sets, kind, false, &from, &at);
    if (std::none_of(from.begin(), from.end(),
                     [](const ConstraintSet* s) { return !s->normals.empty(); }))
        return {};
    std::vector<Vec3> normals;
    for (size_t k = 0; k < faces.size(); ++k)
        normals.push_back(from[k]->normals.empty() ? fallback(faces[k]) : from[k]->normals[at[k]]);
    return normals;
}

} // namespace

std::span<const ConstraintKindInfo> constraint_kinds()
{
    using K = ConstraintKind;
    using S = SolverSettings;
    static const ConstraintKindInfo kinds[kConstraintKinds] = {
        {K::Region, "region", "region", true, false, nullptr, true, {}, palette::kRegion},
        {K::Pin, "pin", "pin", true, false, nullptr, false, {}, palette::kPin},
        {K::Anchor, "anchor", "anchor", true, false, &S::anchor_mu, true, K::Pin, palette::kAnchor},
        {K::Centroid,
         "centroid",
         "centroid",
         false,
         false,
         &S::centroid_mu,
         false,
         {},
         palette::kCentroid},
        {K::Normal, "normal", "normal", false, true, &S::normal_mu, false, {}, palette::kNormal},
        {K::HardNormal,
         "hard_normal",
         "hard normal",
         false,
         true,
         nullptr,
         false,
         {},
         palette::kHardNormal},
        {K::SoftNormal, "soft_normal", "soft normal", false, true, &S::soft_normal_mu, false,
         K::HardNormal, palette::kSoftNormal}};
    return kinds;
}

const ConstraintKindInfo& kind_info(ConstraintKind kind)
{
    return constraint_kinds()[static_cast<size_t>(kind)];
}

std::string_view kind_name(ConstraintKind kind)
{
    return kind_info(kind).name;
}

std::optional<ConstraintKind> kind_named(std::string_view name)
{
    for (const ConstraintKindInfo& k : constraint_kinds())
        if (k.name == name)
            return k.kind;
    return std::nullopt;
}

bool takes_vertices(ConstraintKind kind)
{
    return kind_info(kind).vertices;
}

std::array<float, 3> default_color(ConstraintKind kind)
{
    return kind_info(kind).color;
}

SolverSettings with_pace(SolverSettings settings, const SolverSettings& pace)
{
    settings.iterations_per_frame = pace.iterations_per_frame;
    settings.steps_per_run = pace.steps_per_run;
    settings.until_converged = pace.until_converged;
    return settings;
}

std::optional<SolverSettings> dome_settings(const std::vector<ConstraintSet>& sets,
                                            const SolverSettings& settings)
{
    const bool region = std::ranges::any_of(
        sets, [](const ConstraintSet& s) { return s.kind == ConstraintKind::Region && s.enabled; });
    if (!region)
        return std::nullopt;
    SolverSettings dome = settings;
    if (!solves_for_minimizer(dome.method))
        dome.method = Method::Direct;
    if (!dome.bending)
        dome.bending = Bending{};
    dome.joint = false;
    dome.keep_volume = false;
    dome.optimal_step = false;
    if (dome == settings)
        return std::nullopt;
    return dome;
}

bool takes_weight_map(ConstraintKind kind)
{
    return kind_info(kind).weight_map;
}

Scalar region_anchor_weight(Scalar freedom)
{
    return (1 - freedom) / freedom;
}

bool takes_weight(ConstraintKind kind)
{
    return kind_info(kind).weight != nullptr;
}

Scalar weight_of(const ConstraintSet& set, const SolverSettings& settings)
{
    if (set.mu)
        return *set.mu;
    const ConstraintKindInfo& k = kind_info(set.kind);
    return k.weight != nullptr ? settings.*k.weight : 1;
}

std::vector<std::string> constraint_notes(const std::vector<ConstraintSet>& sets)
{
    std::vector<std::string> notes;
    const auto count_shared = [](const ConstraintSet& a, const ConstraintSet& b) {
        const std::vector<Index> x = sorted(a.vertices.empty() ? a.faces : a.vertices);
        const std::vector<Index> y = sorted(b.vertices.empty() ? b.faces : b.vertices);
        std::vector<Index> both;
        std::set_intersection(x.begin(), x.end(), y.begin(), y.end(), std::back_inserter(both));
        return both.size();
    };
    for (size_t i = 0; i < sets.size(); ++i)
    {
        const ConstraintSet& s = sets[i];
        if (!s.enabled)
            continue;
        if (s.vertices.empty() && s.faces.empty())
        {
            notes.push_back("set " + quoted(s) + " is empty: left out");
            continue;
        }
        const char* what = s.vertices.empty() ? " faces" : " vertices";
        const std::optional<ConstraintKind> winner = kind_info(s.kind).loses_to;
        for (size_t j = 0; j < sets.size(); ++j)
        {
            const ConstraintSet& t = sets[j];
            if (j == i || !t.enabled)
                continue;
            const bool wins = winner && t.kind == *winner;
            const bool earlier = t.kind == s.kind && j < i && s.kind != ConstraintKind::Region;
            if (!wins && !earlier)
                continue;
            if (const size_t n = count_shared(s, t); n > 0)
                notes.push_back(
                    std::to_string(n) + what + " of " + quoted(s) + " are also in " + quoted(t) +
                    (wins ? std::string(": ") +
                                (t.kind == ConstraintKind::Pin ? "pinned" : "fixed") + ", not " +
                                std::string(kind_name(s.kind)) + "ed"
                          : std::string(": ") + quoted(t) + ", earlier in the list, holds them"));
        }
    }
    return notes;
}

std::vector<std::string> constraint_problems(const std::vector<ConstraintSet>& all_sets,
                                             const SolverSettings& settings)
{
    std::vector<std::string> problems;
    std::vector<ConstraintSet> sets; // the enabled ones, empty sets left out
    for (const ConstraintSet& s : all_sets)
        if (s.enabled && !(s.vertices.empty() && s.faces.empty()))
            sets.push_back(s);
    for (const ConstraintSet& s : sets)
        if (!s.weights.empty() &&
            (!takes_weight_map(s.kind) || s.weights.size() != s.vertices.size()))
            problems.push_back("set " + quoted(s) + " has " + std::to_string(s.weights.size()) +
                               " weights for " + std::to_string(s.vertices.size()) + " vertices");
    const bool normal = any_of_kind(sets, ConstraintKind::Normal);
    const bool hard_soft = any_of_kind(sets, ConstraintKind::HardNormal) ||
                           any_of_kind(sets, ConstraintKind::SoftNormal);
    if (hard_soft && !normal)
        problems.push_back(
            "hard and soft normal sets need a normal set (the faces whose "
            "normals move the surface)");
    if (hard_soft && normal && settings.normal_source != NormalSource::Smoothed && !settings.joint)
        problems.push_back(
            "hard and soft normal sets act while normals are smoothed: choose "
            "'smoothed' normals or joint mode");
    if (settings.joint && !normal)
        problems.push_back("joint mode needs a normal set");
    const bool custom = std::any_of(sets.begin(), sets.end(), [](const ConstraintSet& s) {
        return s.kind == ConstraintKind::Normal && !s.normals.empty();
    });
    if (custom && (settings.normal_source == NormalSource::Smoothed || settings.joint))
        problems.push_back(
            "normal sets with their own directions need the 'initial' source and "
            "no joint mode for the other normal sets");
    // A falloff with no region nor pin to fade from is no problem: the whole mesh is free,
    // and the run's note says so (Session::notes).
    if (settings.method == Method::Taubin && (settings.optimal_step || settings.joint))
        problems.push_back("Taubin's method takes a fixed lambda and no joint mode");
    if (settings.method == Method::Taubin && !(settings.taubin_mu < -settings.lambda))
        problems.push_back("Taubin's mu must be below -lambda");
    if (settings.method == Method::Implicit && (settings.optimal_step || settings.joint))
        problems.push_back("implicit steps take their time, no optimal lambda, no joint mode");
    if (solves_for_minimizer(settings.method) && (settings.optimal_step || settings.joint))
        problems.push_back(
            "the direct method solves for the minimizer: no optimal lambda, no joint mode");
    return problems;
}

std::optional<HardVertices> pin_constraints(const std::vector<ConstraintSet>& sets,
                                            std::span<const Scalar> positions)
{
    if (!any_of_kind(sets, ConstraintKind::Pin))
        return std::nullopt;
    std::vector<const ConstraintSet*> from;
    std::vector<size_t> at;
    HardVertices hard{merged(sets, ConstraintKind::Pin, true, &from, &at), {}};
    if (std::any_of(from.begin(), from.end(),
                    [](const ConstraintSet* s) { return !s->targets.empty(); }))
        for (size_t k = 0; k < hard.vertices.size(); ++k)
            hard.targets.push_back(from[k]->targets.empty() ? position(positions, hard.vertices[k])
                                                            : from[k]->targets[at[k]]);
    return hard;
}

Recipe build_recipe(const std::vector<ConstraintSet>& sets, const SolverSettings& settings,
                    const Mesh& mesh, std::span<const Scalar> positions, int iterations)
{
    Recipe r;
    r.iterations = iterations;
    r.optimal_step = settings.optimal_step;
    r.lambda = settings.lambda;
    r.tolerance = settings.tolerance;
    r.method = settings.method;
    r.taubin_mu = settings.taubin_mu;
    r.time = settings.time;
    if (settings.keep_volume)
        r.volume = settings.volume;
    r.prevent_flips = settings.prevent_flips;
    r.falloff = settings.falloff;
    r.bending = settings.bending;
    // A region's weight map: vertices of freedom 0 stay out, those of freedom in (0, 1) are
    // held by anchors of region_anchor_weight after the anchor sets' (which win).
    std::vector<Index> fading;
    std::vector<Scalar> fading_weights;
    if (any_of_kind(sets, ConstraintKind::Region))
    {
        std::vector<const ConstraintSet*> from;
        std::vector<size_t> at;
        std::vector<Index> vertices = merged(sets, ConstraintKind::Region, true, &from, &at);
        size_t kept = 0;
        for (size_t k = 0; k < vertices.size(); ++k)
        {
            const Scalar w = map_value(*from[k], at[k]);
            if (w <= 0)
                continue;
            if (w < 1)
            {
                fading.push_back(vertices[k]);
                fading_weights.push_back(region_anchor_weight(w));
            }
            vertices[kept++] = vertices[k];
        }
        vertices.resize(kept);
        r.region = Region{sorted(std::move(vertices)),
                          sorted(merged(sets, ConstraintKind::Region, false))};
    }
    r.hard = pin_constraints(sets, positions);
    if (any_of_kind(sets, ConstraintKind::Anchor) || !fading.empty())
    {
        std::vector<const ConstraintSet*> from;
        std::vector<size_t> at;
        SoftVertices soft{{false, merged(sets, ConstraintKind::Anchor, true, &from, &at)}, 1, {}};
        std::vector<Scalar> each = element_weights(from, at, settings);
        if (!fading.empty())
        {
            // Not where a pin or an anchor set holds the vertex already.
            std::vector<Index> taken = soft.vertices.indices;
            for (const ConstraintSet& p : sets)
                if (p.kind == ConstraintKind::Pin && p.enabled)
                    taken.insert(taken.end(), p.vertices.begin(), p.vertices.end());
            taken = sorted(std::move(taken));
            for (size_t k = 0; k < fading.size(); ++k)
                if (!std::binary_search(taken.begin(), taken.end(), fading[k]))
                {
                    soft.vertices.indices.push_back(fading[k]);
                    each.push_back(fading_weights[k]);
                }
        }
        collapse(std::move(each), soft.mu, soft.weights);
        if (!soft.vertices.indices.empty()) // every anchor may be pinned
            r.soft = std::move(soft);
    }
    if (any_of_kind(sets, ConstraintKind::Centroid))
    {
        std::vector<const ConstraintSet*> from;
        std::vector<size_t> at;
        CentroidConstraints c{{false, merged(sets, ConstraintKind::Centroid, false, &from, &at)},
                              1,
                              {},
                              settings.denominator};
        weigh(from, at, settings, c.mu, c.weights);
        r.centroid = std::move(c);
    }
    const auto input_normal = [&](Index f) { return face_normal(mesh, positions, f); };
    if (any_of_kind(sets, ConstraintKind::Normal))
    {
        NormalConstraints n;
        std::vector<const ConstraintSet*> from;
        std::vector<size_t> at;
        n.faces.indices = merged(sets, ConstraintKind::Normal, false, &from, &at);
        weigh(from, at, settings, n.mu, n.weights);
        n.source = settings.normal_source;
        n.normals = merged_normals(sets, ConstraintKind::Normal, input_normal);
        if (!n.normals.empty())
            n.source = NormalSource::Custom;
        r.normal = std::move(n);
        if (settings.normal_source == NormalSource::Smoothed || settings.joint)
        {
            NormalSmoothing ns;
            ns.iterations = settings.normal_smoothing_iterations;
            ns.adaptive = settings.adaptive_smoothing;
            ns.lambda = settings.normal_smoothing_lambda;
            ns.hard.faces = merged(sets, ConstraintKind::HardNormal, false);
            ns.hard.normals = merged_normals(sets, ConstraintKind::HardNormal, input_normal);
            std::vector<const ConstraintSet*> soft_from;
            std::vector<size_t> soft_at;
            ns.soft.faces = merged(sets, ConstraintKind::SoftNormal, false, &soft_from, &soft_at);
            ns.soft.mu = settings.soft_normal_mu;
            weigh(soft_from, soft_at, settings, ns.soft.mu, ns.soft.weights);
            ns.soft.normals = merged_normals(sets, ConstraintKind::SoftNormal, input_normal);
            ns.bilateral = settings.bilateral;
            r.normal_smoothing = std::move(ns);
        }
        if (settings.joint)
            r.joint = Joint{settings.gamma};
    }
    return r;
}

bool same_run(const std::vector<ConstraintSet>& a, const SolverSettings& a_settings,
              const std::vector<ConstraintSet>& b, const SolverSettings& b_settings,
              bool ignoring_pin_targets)
{
    if (!(with_pace(a_settings, b_settings) == b_settings) || a.size() != b.size())
        return false;
    for (size_t k = 0; k < a.size(); ++k)
        if (a[k].kind != b[k].kind || a[k].vertices != b[k].vertices || a[k].faces != b[k].faces ||
            a[k].normals != b[k].normals || a[k].enabled != b[k].enabled ||
            a[k].weights != b[k].weights ||
            weight_of(a[k], a_settings) != weight_of(b[k], b_settings) ||
            (!ignoring_pin_targets && a[k].targets != b[k].targets))
            return false;
    return true;
}

ConstraintSet ordered_by(ConstraintSet set, std::span<const Index> vertex_key,
                         std::span<const Index> face_key)
{
    const auto order = [](std::vector<Index>& elements, std::span<const Index> key,
                          auto&... along) {
        std::vector<size_t> k(elements.size());
        for (size_t i = 0; i < k.size(); ++i)
            k[i] = i;
        std::stable_sort(k.begin(), k.end(), [&](size_t a, size_t b) {
            return key[static_cast<size_t>(elements[a])] < key[static_cast<size_t>(elements[b])];
        });
        const auto permute = [&](auto& v) {
            if (v.size() != k.size())
                return; // (no targets, weights or normals of its own)
            auto copy = v;
            for (size_t i = 0; i < k.size(); ++i)
                v[i] = copy[k[i]];
        };
        (permute(along), ...);
        permute(elements);
    };
    order(set.vertices, vertex_key, set.targets, set.weights);
    order(set.faces, face_key, set.normals);
    return set;
}

std::vector<Index> region_holes(const ConstraintSet& set, const Mesh& mesh,
                                const Topology& topology)
{
    // On the vertices the region moves (a region of faces moves their vertices): those it
    // leaves out with every neighbour within a ring of it, what closing it adds.
    SelectionMask moving(static_cast<size_t>(mesh.vertex_count()), 0);
    apply_selection(moving, set.vertices, SelectOp::Add);
    if (!set.faces.empty())
    {
        SelectionMask faces(static_cast<size_t>(mesh.face_count()), 0);
        apply_selection(faces, set.faces, SelectOp::Add);
        const SelectionMask of_faces = vertices_of_faces(mesh, faces);
        for (size_t k = 0; k < moving.size(); ++k)
            moving[k] = moving[k] || of_faces[k];
    }
    SelectionMask closed = shrink_vertices(topology, grow_vertices(topology, moving));
    // The parts left out, and the mesh's components, by a walk over the edges.
    const Index n = mesh.vertex_count();
    const auto label = [&](auto&& within) {
        std::vector<Index> part(static_cast<size_t>(n), kInvalidIndex);
        std::vector<Index> stack;
        Index parts = 0;
        for (Index v = 0; v < n; ++v)
        {
            if (part[v] != kInvalidIndex || !within(v))
                continue;
            part[v] = parts;
            stack.push_back(v);
            while (!stack.empty())
            {
                const Index i = stack.back();
                stack.pop_back();
                for (const Index j : topology.neighbors(i))
                    if (part[j] == kInvalidIndex && within(j))
                    {
                        part[j] = parts;
                        stack.push_back(j);
                    }
            }
            ++parts;
        }
        return std::pair{std::move(part), parts};
    };
    const auto [left_part, left_parts] = label([&](Index v) { return !moving[v]; });
    const auto [component, components] = label([](Index) { return true; });
    std::vector<size_t> part_size(static_cast<size_t>(left_parts), 0),
        region_size(static_cast<size_t>(components), 0);
    std::vector<Index> part_component(static_cast<size_t>(left_parts), 0);
    for (Index v = 0; v < n; ++v)
        if (moving[v])
            ++region_size[component[v]];
        else
        {
            ++part_size[left_part[v]];
            part_component[left_part[v]] = component[v];
        }
    // Each component's largest part left out is the rest of the mesh (the first, on a tie).
    std::vector<Index> rest(static_cast<size_t>(components), kInvalidIndex);
    for (Index p = 0; p < left_parts; ++p)
    {
        Index& r = rest[part_component[p]];
        if (r == kInvalidIndex || part_size[p] > part_size[r])
            r = p;
    }
    std::vector<char> enclosed(static_cast<size_t>(left_parts), 0);
    for (Index p = 0; p < left_parts; ++p)
        enclosed[p] =
            p != rest[part_component[p]] && 4 * part_size[p] <= region_size[part_component[p]];
    std::vector<Index> holes;
    for (Index v = 0; v < n; ++v)
        if (!moving[v] && (closed[v] || enclosed[left_part[v]]))
            holes.push_back(v);
    return holes;
}

size_t close_region_holes(ConstraintSet& set, const Mesh& mesh, const Topology& topology)
{
    const std::vector<Index> holes = region_holes(set, mesh, topology);
    if (holes.empty())
        return 0;
    if (set.faces.empty())
        set.vertices.insert(set.vertices.end(), holes.begin(), holes.end());
    else
    {
        // A region of faces takes the faces around the holes whose corners all move then.
        SelectionMask faces(static_cast<size_t>(mesh.face_count()), 0);
        apply_selection(faces, set.faces, SelectOp::Add);
        SelectionMask moving = vertices_of_faces(mesh, faces);
        apply_selection(moving, set.vertices, SelectOp::Add);
        apply_selection(moving, holes, SelectOp::Add);
        const SelectionMask around = faces_of_vertices(mesh, moving);
        for (size_t f = 0; f < faces.size(); ++f)
            if (around[f] && !faces[f])
                set.faces.push_back(static_cast<Index>(f));
        std::sort(set.faces.begin(), set.faces.end());
    }
    if (set.weights.empty())
        std::sort(set.vertices.begin(), set.vertices.end());
    else
    {
        // A weight map follows its vertices; the holes move freely (1).
        set.weights.resize(set.vertices.size(), 1);
        std::vector<std::pair<Index, Scalar>> pairs;
        for (size_t k = 0; k < set.vertices.size(); ++k)
            pairs.emplace_back(set.vertices[k], set.weights[k]);
        std::sort(pairs.begin(), pairs.end(),
                  [](const auto& a, const auto& b) { return a.first < b.first; });
        for (size_t k = 0; k < pairs.size(); ++k)
            std::tie(set.vertices[k], set.weights[k]) = pairs[k];
    }
    return holes.size();
}

std::vector<ConstraintSet> merge_preset(const std::vector<ConstraintSet>& user,
                                        std::vector<ConstraintSet> preset)
{
    const auto has = [](const std::vector<ConstraintSet>& sets, ConstraintKind kind) {
        return std::any_of(sets.begin(), sets.end(),
                           [&](const ConstraintSet& s) { return s.kind == kind; });
    };
    const auto placement = [](ConstraintKind kind) {
        return kind == ConstraintKind::Region || kind == ConstraintKind::Pin;
    };
    std::vector<ConstraintSet> out;
    for (const ConstraintSet& s : user)
        if (placement(s.kind) || !has(preset, s.kind))
            out.push_back(s);
    for (ConstraintSet& s : preset)
        if (!placement(s.kind) || !has(user, s.kind))
        {
            // A name of its own: "normal" may be a user's set already.
            const std::string base = s.name;
            for (int n = 2; std::any_of(out.begin(), out.end(),
                                        [&](const ConstraintSet& o) { return o.name == s.name; });
                 ++n)
                s.name = base + " " + std::to_string(n);
            out.push_back(std::move(s));
        }
    return out;
}

ImportedRecipe sets_from_recipe(const Recipe& r, const Mesh& mesh)
{
    ImportedRecipe out;
    out.iterations = r.iterations;
    out.description = r.description;
    SolverSettings& s = out.settings;
    s.optimal_step = r.optimal_step;
    s.lambda = r.lambda;
    s.tolerance = r.tolerance;
    const auto all = [](const IndexSet& set, Index n) {
        if (!set.all)
            return set.indices;
        std::vector<Index> v(static_cast<size_t>(n));
        for (Index i = 0; i < n; ++i)
            v[static_cast<size_t>(i)] = i;
        return v;
    };
    const auto add = [&](ConstraintKind kind, std::vector<Index> vertices,
                         std::vector<Index> faces) -> ConstraintSet& {
        ConstraintSet set;
        set.name = std::string(kind_name(kind));
        set.kind = kind;
        set.vertices = std::move(vertices);
        set.faces = std::move(faces);
        set.color = default_color(kind);
        out.sets.push_back(std::move(set));
        return out.sets.back();
    };
    // A section with per-element weights: one set per run of equal weights, each with its
    // own mu (the sets of a recipe exported with several weights come back as they were);
    // without weights, one set with the kind's mu. Vertices weighted by more runs than
    // kMaxWeightRuns: one set with a weight map (a painted map, which would be a set per
    // vertex).
    constexpr size_t kMaxWeightRuns = 16;
    const auto add_weighted = [&](ConstraintKind kind, const std::vector<Index>& elements,
                                  Scalar mu, const std::vector<Scalar>& weights, Scalar& kind_mu,
                                  std::vector<Vec3> normals = {}) {
        const bool vertices = takes_vertices(kind);
        if (weights.empty())
        {
            kind_mu = mu;
            ConstraintSet& set = vertices ? add(kind, elements, {}) : add(kind, {}, elements);
            set.normals = std::move(normals);
            return;
        }
        // A painted map (more than a few values) comes back as one set with its map.
        size_t runs = 1;
        for (size_t k = 1; k < weights.size(); ++k)
            runs += weights[k] != weights[k - 1] ? 1 : 0;
        if (vertices && runs > kMaxWeightRuns)
        {
            ConstraintSet& set = add(kind, elements, {});
            set.mu = mu;
            set.weights = weights;
            return;
        }
        for (size_t begin = 0, end; begin < elements.size(); begin = end)
        {
            end = begin + 1;
            while (end < elements.size() && weights[end] == weights[begin])
                ++end;
            const std::vector<Index> part(elements.begin() + static_cast<std::ptrdiff_t>(begin),
                                          elements.begin() + static_cast<std::ptrdiff_t>(end));
            ConstraintSet& set = vertices ? add(kind, part, {}) : add(kind, {}, part);
            set.mu = mu * weights[begin];
            if (!normals.empty())
                set.normals.assign(normals.begin() + static_cast<std::ptrdiff_t>(begin),
                                   normals.begin() + static_cast<std::ptrdiff_t>(end));
            if (begin > 0)
                set.name += " " + std::to_string(out.sets.size());
        }
    };
    if (r.region)
        add(ConstraintKind::Region, sorted(r.region->vertices), sorted(r.region->faces));
    if (r.hard)
        add(ConstraintKind::Pin, r.hard->vertices, {}).targets = r.hard->targets;
    if (r.soft)
    {
        std::vector<Index> v = all(r.soft->vertices, mesh.vertex_count());
        if (r.soft->vertices.all && r.hard) // "all" = every vertex that is not hard
        {
            const std::vector<Index> hard = sorted(r.hard->vertices);
            std::erase_if(v,
                          [&](Index i) { return std::binary_search(hard.begin(), hard.end(), i); });
        }
        std::vector<Scalar> w = r.soft->weights;
        if (!w.empty() && r.soft->vertices.all) // per mesh vertex: those kept
        {
            std::vector<Scalar> kept;
            for (const Index i : v)
                kept.push_back(w[static_cast<size_t>(i)]);
            w = std::move(kept);
        }
        add_weighted(ConstraintKind::Anchor, v, r.soft->mu, w, s.anchor_mu);
    }
    if (r.centroid)
    {
        add_weighted(ConstraintKind::Centroid, all(r.centroid->faces, mesh.face_count()),
                     r.centroid->mu, r.centroid->weights, s.centroid_mu);
        s.denominator = r.centroid->denominator;
    }
    if (r.normal)
    {
        add_weighted(
            ConstraintKind::Normal, all(r.normal->faces, mesh.face_count()), r.normal->mu,
            r.normal->weights, s.normal_mu,
            r.normal->source == NormalSource::Custom ? r.normal->normals : std::vector<Vec3>{});
        if (r.normal->source != NormalSource::Custom)
            s.normal_source = r.normal->source;
    }
    if (r.normal_smoothing)
    {
        s.normal_smoothing_iterations = r.normal_smoothing->iterations;
        s.adaptive_smoothing = r.normal_smoothing->adaptive;
        s.normal_smoothing_lambda = r.normal_smoothing->lambda;
        if (!r.normal_smoothing->hard.faces.empty())
            add(ConstraintKind::HardNormal, {}, r.normal_smoothing->hard.faces).normals =
                r.normal_smoothing->hard.normals;
        if (!r.normal_smoothing->soft.faces.empty())
        {
            add_weighted(ConstraintKind::SoftNormal, r.normal_smoothing->soft.faces,
                         r.normal_smoothing->soft.mu, r.normal_smoothing->soft.weights,
                         s.soft_normal_mu, r.normal_smoothing->soft.normals);
        }
    }
    if (r.joint)
    {
        s.joint = true;
        s.gamma = r.joint->gamma;
    }
    // The editor runs Jacobi steps, Taubin's pairs or the direct method; gradient descent
    // comes in as Jacobi.
    s.method = r.method == Method::GradientDescent ? Method::Jacobi : r.method;
    s.bending = r.bending;
    s.taubin_mu = r.taubin_mu;
    s.time = r.time;
    if (r.normal_smoothing)
        s.bilateral = r.normal_smoothing->bilateral;
    s.keep_volume = r.volume.has_value();
    s.volume = r.volume.value_or(KeepVolume{});
    s.prevent_flips = r.prevent_flips;
    s.falloff = r.falloff;
    return out;
}

} // namespace meshfair::app
