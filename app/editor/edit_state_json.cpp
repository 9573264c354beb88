// SPDX-License-Identifier: MIT
// Copyright 2026 the MeshFair authors.
#include "app/editor/edit_state_json.h"

#include <cstdint>
#include <limits>
#include <string>

#include "core/recipe/recipe_json.h"

namespace meshfair::app {

namespace {

using Json = nlohmann::json;

// The state file's numbers: what no editor writes is damage.
Scalar real_at(const CheckedJson& j, const char* key, bool zero_allowed)
{
    const CheckedJson v = j[key];
    const Scalar x = v.number();
    if (x < 0 || (x == 0 && !zero_allowed))
        v.fail(std::string("must be a number ") + (zero_allowed ? ">= 0" : "> 0"));
    return x;
}
Scalar positive_at(const CheckedJson& j, const char* key)
{
    return real_at(j, key, false);
}
Scalar non_negative_at(const CheckedJson& j, const char* key)
{
    return real_at(j, key, true);
}
// A flag that files of earlier versions may lack.
bool flag_at(const CheckedJson& j, const char* key, bool fallback)
{
    const std::optional<CheckedJson> v = j.find(key);
    return v ? v->boolean() : fallback;
}
// An object that may be null (none) or, in files of earlier versions, absent.
std::optional<CheckedJson> object_at(const CheckedJson& j, const char* key)
{
    std::optional<CheckedJson> v = j.find(key);
    return v && !v->is_null() ? v : std::nullopt;
}

} // namespace

int count_at(const CheckedJson& j, const char* key, int lo)
{
    const CheckedJson v = j[key];
    const auto& raw = v.raw();
    if (!raw.is_number_integer() || raw.get<std::int64_t>() < lo ||
        raw.get<std::int64_t>() > std::numeric_limits<int>::max())
        v.fail("must be an integer from " + std::to_string(lo) + " to 2147483647");
    return static_cast<int>(raw.get<std::int64_t>());
}

namespace {

Json vec3s(const std::vector<Vec3>& v)
{
    Json j = Json::array();
    for (const Vec3& p : v)
        j.push_back({p[0], p[1], p[2]});
    return j;
}

std::vector<Vec3> vec3s_of(const CheckedJson& j)
{
    std::vector<Vec3> v;
    for (const CheckedJson& p : j.elements())
        v.push_back(p.vec3());
    return v;
}

} // namespace

Json set_json(const ConstraintSet& s)
{
    return {{"name", s.name},
            {"kind", std::string(kind_name(s.kind))},
            {"vertices", index_list_json(s.vertices)},
            {"faces", index_list_json(s.faces)},
            {"targets", vec3s(s.targets)},
            {"normals", vec3s(s.normals)},
            {"color", s.color},
            {"visible", s.visible},
            {"enabled", s.enabled},
            {"mu", s.mu ? Json(*s.mu) : Json(nullptr)},
            {"weights", s.weights}};
}

namespace {

// Element indices in [0, end), as a list or runs (parse_index_list): `what` names them.
std::vector<Index> indices_of(const CheckedJson& j, Index end, const char* what)
{
    const std::string refusal = std::string("must be indices of this mesh's ") + what;
    std::int64_t budget = end; // a set lists each element at most once
    std::vector<Index> out;
    try
    {
        out = parse_index_list(j, budget);
    }
    catch (const JsonValueError& e)
    {
        j.fail(refusal + " (" + e.path() + ": " + e.why() + ")");
    }
    for (const Index i : out)
        if (i >= end)
            j.fail(refusal);
    return out;
}

} // namespace

ConstraintSet set_of(const CheckedJson& j, Index vertices, Index faces)
{
    ConstraintSet s;
    s.name = j["name"].text();
    const std::optional<ConstraintKind> kind = kind_named(j["kind"].text());
    if (!kind)
        j["kind"].fail("is not a set kind");
    s.kind = *kind;
    s.vertices = indices_of(j["vertices"], vertices, "vertices");
    s.faces = indices_of(j["faces"], faces, "faces");
    s.targets = vec3s_of(j["targets"]);
    s.normals = vec3s_of(j["normals"]);
    if (!s.targets.empty() && s.targets.size() != s.vertices.size())
        j["targets"].fail("must be one per vertex");
    if (!s.normals.empty() && s.normals.size() != s.faces.size())
        j["normals"].fail("must be one per face");
    const CheckedJson color = j["color"];
    if (!color.is_array() || color.size() != 3)
        color.fail("must be a colour [r, g, b]");
    for (size_t c = 0; c < 3; ++c)
    {
        const Scalar v = color.at(c).number();
        if (!(v >= 0 && v <= 1))
            color.at(c).fail("must be in [0, 1] (a colour must be fractions)");
        s.color[c] = static_cast<float>(v);
    }
    s.visible = j["visible"].boolean();
    s.enabled = flag_at(j, "enabled", true); // files of earlier versions have neither
    if (object_at(j, "mu"))
        s.mu = non_negative_at(j, "mu");
    if (const auto weights = j.find("weights")) // earlier files have no maps
    {
        s.weights = weights->numbers(
            0, s.kind == ConstraintKind::Region ? 1 : std::numeric_limits<double>::infinity());
        if (!s.weights.empty() &&
            (s.weights.size() != s.vertices.size() || !takes_weight_map(s.kind)))
            weights->fail(
                "does not fit: a weight map needs an anchor or region set, and one "
                "weight per vertex");
    }
    return s;
}

Json settings_json(const SolverSettings& s)
{
    return {{"optimal_step", s.optimal_step},
            {"lambda", s.lambda},
            {"tolerance", s.tolerance},
            {"iterations_per_frame", s.iterations_per_frame},
            {"steps_per_run", s.steps_per_run},
            {"until_converged", s.until_converged},
            {"anchor_mu", s.anchor_mu},
            {"centroid_mu", s.centroid_mu},
            {"exact_denominator", s.denominator == CentroidDenominator::Exact},
            {"normal_mu", s.normal_mu},
            {"smoothed_normals", s.normal_source == NormalSource::Smoothed},
            {"normal_smoothing_iterations", s.normal_smoothing_iterations},
            {"adaptive_smoothing", s.adaptive_smoothing
                                       ? Json{{"per_noise", s.adaptive_smoothing->per_noise},
                                              {"strength", s.adaptive_smoothing->strength}}
                                       : Json(nullptr)},
            {"normal_smoothing_lambda", s.normal_smoothing_lambda},
            {"soft_normal_mu", s.soft_normal_mu},
            {"joint", s.joint},
            {"gamma", s.gamma},
            {"taubin", s.method == Method::Taubin},
            {"direct", s.method == Method::Direct},
            {"cg", s.method == Method::ConjugateGradient},
            {"implicit", s.method == Method::Implicit},
            {"time", s.time},
            {"taubin_mu", s.taubin_mu},
            {"bilateral", s.bilateral ? bilateral_json(*s.bilateral) : Json(nullptr)},
            {"keep_volume", s.keep_volume},
            {"volume_open_capped", s.volume.open == OpenVolume::Capped},
            {"volume_free_components", s.volume.free_components_only},
            {"prevent_flips", s.prevent_flips},
            {"falloff", s.falloff ? falloff_json(*s.falloff) : Json(nullptr)},
            {"bending", s.bending ? bending_json(*s.bending) : Json(nullptr)}};
}

SolverSettings settings_of(const CheckedJson& j)
{
    SolverSettings s;
    s.optimal_step = j["optimal_step"].boolean();
    s.lambda = positive_at(j, "lambda");
    s.tolerance = non_negative_at(j, "tolerance");
    s.iterations_per_frame = count_at(j, "iterations_per_frame", 1);
    if (j.has("steps_per_run")) // older files have none
        s.steps_per_run = count_at(j, "steps_per_run", 1);
    s.until_converged = flag_at(j, "until_converged", s.until_converged);
    s.anchor_mu = non_negative_at(j, "anchor_mu");
    s.centroid_mu = non_negative_at(j, "centroid_mu");
    s.denominator =
        j["exact_denominator"].boolean() ? CentroidDenominator::Exact : CentroidDenominator::Paper;
    s.normal_mu = non_negative_at(j, "normal_mu");
    s.normal_source =
        j["smoothed_normals"].boolean() ? NormalSource::Smoothed : NormalSource::Initial;
    s.normal_smoothing_iterations = count_at(j, "normal_smoothing_iterations", 0);
    if (const auto adaptive = object_at(j, "adaptive_smoothing")) // older: none
        s.adaptive_smoothing = AdaptiveIterations{non_negative_at(*adaptive, "per_noise"),
                                                  non_negative_at(*adaptive, "strength")};
    s.normal_smoothing_lambda = positive_at(j, "normal_smoothing_lambda");
    s.soft_normal_mu = non_negative_at(j, "soft_normal_mu");
    s.joint = j["joint"].boolean();
    s.gamma = non_negative_at(j, "gamma");
    // Older files have none of these: the defaults (Jacobi, uniform weights, no volume).
    s.method = flag_at(j, "taubin", false)     ? Method::Taubin
               : flag_at(j, "direct", false)   ? Method::Direct
               : flag_at(j, "cg", false)       ? Method::ConjugateGradient
               : flag_at(j, "implicit", false) ? Method::Implicit
                                               : Method::Jacobi;
    if (const auto time = j.find("time"))
        s.time = time->positive();
    if (const auto mu = j.find("taubin_mu"))
        s.taubin_mu = mu->number();
    if (const auto b = object_at(j, "bilateral"))
        s.bilateral = parse_bilateral(*b);
    s.keep_volume = flag_at(j, "keep_volume", false);
    s.volume.open = flag_at(j, "volume_open_capped", true) ? OpenVolume::Capped : OpenVolume::None;
    s.volume.free_components_only = flag_at(j, "volume_free_components", false);
    s.prevent_flips = flag_at(j, "prevent_flips", false);
    if (const auto f = object_at(j, "falloff"))
        s.falloff = parse_falloff(*f);
    if (const auto b = object_at(j, "bending"))
        s.bending = parse_bending(*b);
    return s;
}

} // namespace meshfair::app
