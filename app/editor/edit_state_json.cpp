// SPDX-License-Identifier: MIT
// Copyright 2026 the MeshFair authors.
#include "app/editor/edit_state_json.h"

#include <cmath>
#include <cstdint>
#include <limits>
#include <stdexcept>
#include <string>

#include "core/recipe/recipe_json.h"

namespace meshfair::app {

namespace {

using Json = nlohmann::json;

Scalar finite_of(const Json& j)
{
    const Scalar v = j.get<Scalar>();
    if (!std::isfinite(v))
        throw std::invalid_argument("a coordinate is not a finite number");
    return v;
}

// The state file's numbers: what no editor writes is damage. `j` holds `key`.
Scalar real_at(const Json& j, const char* key, bool zero_allowed)
{
    const Scalar v = j.at(key).get<Scalar>();
    if (!std::isfinite(v) || v < 0 || (v == 0 && !zero_allowed))
        throw std::invalid_argument(std::string(key) + " must be a number " +
                                    (zero_allowed ? ">= 0" : "> 0"));
    return v;
}
Scalar positive_at(const Json& j, const char* key)
{
    return real_at(j, key, false);
}
Scalar non_negative_at(const Json& j, const char* key)
{
    return real_at(j, key, true);
}
} // namespace

int count_at(const Json& j, const char* key, int lo)
{
    const Json& v = j.at(key);
    if (!v.is_number_integer() || v.get<std::int64_t>() < lo ||
        v.get<std::int64_t>() > std::numeric_limits<int>::max())
        throw std::invalid_argument(std::string(key) + " must be an integer from " +
                                    std::to_string(lo) + " to 2147483647");
    return static_cast<int>(v.get<std::int64_t>());
}

namespace {

Json vec3s(const std::vector<Vec3>& v)
{
    Json j = Json::array();
    for (const Vec3& p : v)
        j.push_back({p[0], p[1], p[2]});
    return j;
}

std::vector<Vec3> vec3s_of(const Json& j)
{
    if (!j.is_array())
        throw std::invalid_argument("targets and normals must be lists");
    std::vector<Vec3> v;
    for (const Json& p : j)
    {
        if (!p.is_array() || p.size() != 3)
            throw std::invalid_argument("a point or normal must be [x, y, z]");
        v.push_back({finite_of(p[0]), finite_of(p[1]), finite_of(p[2])});
    }
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
std::vector<Index> indices_of(const Json& j, Index end, const char* what)
{
    std::int64_t budget = end; // a set lists each element at most once
    std::vector<Index> out;
    try
    {
        out = parse_index_list(j, std::string(what), budget);
    }
    catch (const RecipeError& e)
    {
        throw std::invalid_argument(std::string("a set's ") + what +
                                    " must be indices of this mesh's " + what + " (" + e.key() +
                                    ": " + e.message() + ")");
    }
    for (const Index i : out)
        if (i >= end)
            throw std::invalid_argument(std::string("a set's ") + what +
                                        " must be indices of this mesh's " + what);
    return out;
}

} // namespace

ConstraintSet set_of(const Json& j, Index vertices, Index faces)
{
    ConstraintSet s;
    s.name = j.at("name").get<std::string>();
    const std::optional<ConstraintKind> kind = kind_named(j.at("kind").get<std::string>());
    if (!kind)
        throw std::invalid_argument("unknown set kind");
    s.kind = *kind;
    s.vertices = indices_of(j.at("vertices"), vertices, "vertices");
    s.faces = indices_of(j.at("faces"), faces, "faces");
    s.targets = vec3s_of(j.at("targets"));
    s.normals = vec3s_of(j.at("normals"));
    if (!s.targets.empty() && s.targets.size() != s.vertices.size())
        throw std::invalid_argument("a set's targets must be one per vertex");
    if (!s.normals.empty() && s.normals.size() != s.faces.size())
        throw std::invalid_argument("a set's normals must be one per face");
    const Json& color = j.at("color");
    if (!color.is_array() || color.size() != 3)
        throw std::invalid_argument("a set's colour must be [r, g, b]");
    for (int c = 0; c < 3; ++c)
    {
        const Scalar v = color[static_cast<size_t>(c)].get<Scalar>();
        if (!(v >= 0 && v <= 1))
            throw std::invalid_argument("a set's colour must be fractions in [0, 1]");
        s.color[static_cast<size_t>(c)] = static_cast<float>(v);
    }
    s.visible = j.at("visible").get<bool>();
    s.enabled = j.value("enabled", true); // files of earlier versions have neither
    if (j.contains("mu") && !j.at("mu").is_null())
        s.mu = non_negative_at(j, "mu");
    s.weights = j.value("weights", std::vector<Scalar>{}); // earlier files have no maps
    if (!s.weights.empty() && (s.weights.size() != s.vertices.size() || !takes_weight_map(s.kind)))
        throw std::invalid_argument(
            "a weight map needs an anchor or region set, and one "
            "weight per vertex");
    for (const Scalar w : s.weights)
        if (!(w >= 0) || !std::isfinite(w) || (s.kind == ConstraintKind::Region && w > 1))
            throw std::invalid_argument(
                "a weight map's values must be in [0, 1] (region) or "
                ">= 0 (anchor)");
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

SolverSettings settings_of(const Json& j)
{
    SolverSettings s;
    s.optimal_step = j.at("optimal_step").get<bool>();
    s.lambda = positive_at(j, "lambda");
    s.tolerance = non_negative_at(j, "tolerance");
    s.iterations_per_frame = count_at(j, "iterations_per_frame", 1);
    if (j.contains("steps_per_run")) // older files have none
        s.steps_per_run = count_at(j, "steps_per_run", 1);
    s.until_converged = j.value("until_converged", s.until_converged);
    s.anchor_mu = non_negative_at(j, "anchor_mu");
    s.centroid_mu = non_negative_at(j, "centroid_mu");
    s.denominator = j.at("exact_denominator").get<bool>() ? CentroidDenominator::Exact
                                                          : CentroidDenominator::Paper;
    s.normal_mu = non_negative_at(j, "normal_mu");
    s.normal_source =
        j.at("smoothed_normals").get<bool>() ? NormalSource::Smoothed : NormalSource::Initial;
    s.normal_smoothing_iterations = count_at(j, "normal_smoothing_iterations", 0);
    if (j.contains("adaptive_smoothing") && !j["adaptive_smoothing"].is_null()) // older: none
        s.adaptive_smoothing =
            AdaptiveIterations{non_negative_at(j["adaptive_smoothing"], "per_noise"),
                               non_negative_at(j["adaptive_smoothing"], "strength")};
    s.normal_smoothing_lambda = positive_at(j, "normal_smoothing_lambda");
    s.soft_normal_mu = non_negative_at(j, "soft_normal_mu");
    s.joint = j.at("joint").get<bool>();
    s.gamma = non_negative_at(j, "gamma");
    // Older files have none of these: the defaults (Jacobi, uniform weights, no volume).
    s.method = j.value("taubin", false)     ? Method::Taubin
               : j.value("direct", false)   ? Method::Direct
               : j.value("cg", false)       ? Method::ConjugateGradient
               : j.value("implicit", false) ? Method::Implicit
                                            : Method::Jacobi;
    if (j.contains("time"))
    {
        s.time = j.at("time").get<Scalar>();
        if (!(std::isfinite(s.time) && s.time > 0))
            throw std::invalid_argument("time must be a finite number > 0");
    }
    if (j.contains("taubin_mu"))
    {
        s.taubin_mu = j.at("taubin_mu").get<Scalar>();
        if (!std::isfinite(s.taubin_mu))
            throw std::invalid_argument("taubin_mu must be a finite number");
    }
    if (j.contains("bilateral") && !j["bilateral"].is_null())
        s.bilateral = parse_bilateral(j["bilateral"], "settings.bilateral");
    s.keep_volume = j.value("keep_volume", false);
    s.volume.open = j.value("volume_open_capped", true) ? OpenVolume::Capped : OpenVolume::None;
    s.volume.free_components_only = j.value("volume_free_components", false);
    s.prevent_flips = j.value("prevent_flips", false);
    if (j.contains("falloff") && !j["falloff"].is_null())
        s.falloff = parse_falloff(j["falloff"], "settings.falloff");
    if (j.contains("bending") && !j["bending"].is_null())
        s.bending = parse_bending(j["bending"], "settings.bending");
    return s;
}

} // namespace meshfair::app
