// SPDX-License-Identifier: MIT
// Copyright 2026 the MeshFair authors.
#include "core/recipe/recipe_json.h"

#include <cmath>
#include <initializer_list>
#include <limits>
#include <string_view>

#include "core/errors.h"
#include "core/io/io.h"

namespace meshfair {

namespace {

using Json = nlohmann::json;

std::string child(const std::string& key, const std::string& name)
{
    return key.empty() ? name : key + "." + name;
}

//! Which of `names` the string `value` is (its index).
//! \throw RecipeError naming `key`: must be "a", "b" or "c".
size_t choice(const Json& value, const std::string& key,
              std::initializer_list<std::string_view> names)
{
    size_t k = 0;
    std::string listed;
    for (const std::string_view name : names)
    {
        if (value.is_string() && value.get_ref<const std::string&>() == name)
            return k;
        listed += std::string(k == 0                  ? ""
                              : k + 1 == names.size() ? " or "
                                                      : ", ") +
                  "\"" + std::string(name) + "\"";
        ++k;
    }
    throw RecipeError(key, "must be " + listed);
}

void expect_object(const Json& j, const std::string& key,
                   std::initializer_list<std::string_view> allowed)
{
    if (!j.is_object())
        throw RecipeError(key.empty() ? "(top level)" : key, "must be an object");
    for (const auto& [name, value] : j.items())
    {
        bool known = false;
        for (const auto a : allowed)
            known = known || name == a;
        if (!known)
        {
            std::string list;
            for (const auto a : allowed)
                list += (list.empty() ? "" : ", ") + std::string(a);
            throw RecipeError(child(key, name), list.empty()
                                                    ? "unknown key (this section takes none)"
                                                    : "unknown key (allowed here: " + list + ")");
        }
    }
}

// A value for an error message: scalars as written, containers by kind only, so a
// message never grows with (nor recurses into) whatever the file nests there.
std::string describe(const Json& j)
{
    if (j.is_array())
        return "an array";
    if (j.is_object())
        return "an object";
    std::string text = j.dump();
    if (text.size() > 40)
        text = text.substr(0, 40) + "...";
    return text;
}

Scalar number(const Json& j, const std::string& key)
{
    if (!j.is_number())
        throw RecipeError(key, "must be a number");
    const Scalar v = j.get<Scalar>();
    if (!std::isfinite(v))
        throw RecipeError(key, "must be finite");
    return v;
}

Scalar weight(const Json& j, const std::string& key)
{
    const Scalar v = number(j, key);
    if (v < 0)
        throw RecipeError(key, "must be >= 0 (got " + describe(j) + ")");
    return v;
}

std::int64_t integer(const Json& j, const std::string& key)
{
    if (j.is_number_integer())
        return j.get<std::int64_t>();
    // Integers past uint64 arrive as doubles.
    if (j.is_number_unsigned() || (j.is_number_float() && std::abs(j.get<double>()) >= 9.2e18))
        throw RecipeError(key, "is out of range (got " + describe(j) + ")");
    throw RecipeError(key, "must be an integer (got " + describe(j) + ")");
}

int count(const Json& j, const std::string& key)
{
    const std::int64_t v = integer(j, key);
    if (v < 0 || v > std::numeric_limits<int>::max())
        throw RecipeError(key, "must be an integer in [0, 2147483647] (got " + describe(j) + ")");
    return static_cast<int>(v);
}

// The indices the recipe being parsed may still list (RecipeLimits::max_listed): set by
// parse_recipe for its thread, taken from by every index list.
thread_local std::int64_t listed_left = RecipeLimits{}.max_listed;

std::vector<Index> indices(const Json& j, const std::string& key)
{
    return parse_index_list(j, key, listed_left);
}

IndexSet index_set(const Json& j, const std::string& key)
{
    IndexSet s;
    if (j.is_string())
    {
        if (j.get<std::string>() != "all")
            throw RecipeError(key, "must be \"all\" or an array of indices");
        s.all = true;
        return s;
    }
    s.indices = indices(j, key);
    return s;
}

std::vector<Vec3> points(const Json& j, const std::string& key)
{
    if (!j.is_array())
        throw RecipeError(key, "must be an array of [x, y, z] triples");
    std::vector<Vec3> out;
    out.reserve(j.size());
    for (size_t k = 0; k < j.size(); ++k)
    {
        const Json& p = j[k];
        if (!p.is_array() || p.size() != 3)
            throw RecipeError(recipe_item_key(key, k), "must be an [x, y, z] triple");
        Vec3 v;
        for (size_t a = 0; a < 3; ++a)
            v[a] = number(p[a], recipe_item_key(recipe_item_key(key, k), a));
        out.push_back(v);
    }
    return out;
}

Scalar step_length(const Json& j, const std::string& key)
{
    const Scalar v = number(j, key);
    if (!(v > 0))
        throw RecipeError(key, "must be > 0 (got " + describe(j) + ")");
    return v;
}

std::vector<Scalar> weights(const Json& j, const std::string& key)
{
    if (!j.is_array())
        throw RecipeError(key, "must be an array of numbers >= 0");
    std::vector<Scalar> out;
    out.reserve(j.size());
    for (size_t k = 0; k < j.size(); ++k)
        out.push_back(weight(j[k], recipe_item_key(key, k)));
    return out;
}

// The sets a section gives: one object, or a non-empty array of them (each parsed by
// parse_one with its key, "soft[1]").
template <typename Set, typename ParseOne>
std::vector<Set> sets_of(const Json& j, const std::string& key, ParseOne parse_one)
{
    if (j.is_object())
        return {parse_one(j, key)};
    if (!j.is_array())
        throw RecipeError(key, "must be an object or an array of objects");
    if (j.empty())
        throw RecipeError(key, "must hold at least one set (leave the section out for none)");
    std::vector<Set> sets;
    sets.reserve(j.size());
    for (size_t k = 0; k < j.size(); ++k)
        sets.push_back(parse_one(j[k], recipe_item_key(key, k)));
    return sets;
}

// The rules of a list of sets that need no mesh, for the sets' element lists (named `list`,
// e.g. "vertices") and their targets or normals: "all" only alone; targets given by every
// set or by none, one per element, as weights are.
template <typename Set>
void check_set_list(const std::vector<Set>& sets, const std::string& key, const char* list,
                    IndexSet Set::*elements, const char* targets_name,
                    std::vector<Vec3> Set::*targets)
{
    for (size_t k = 0; k < sets.size(); ++k)
    {
        const std::string set = recipe_item_key(key, k);
        const IndexSet& e = sets[k].*elements;
        if (e.all)
            throw RecipeError(child(set, list), "\"all\" is allowed only when " + key +
                                                    " holds one set (this list holds " +
                                                    std::to_string(sets.size()) + ")");
        const size_t count = e.indices.size(), given = (sets[k].*targets).size();
        if ((given == 0) != (sets[0].*targets).empty())
            throw RecipeError(child(set, targets_name),
                              std::string(given == 0 ? "is missing" : "is given") + ", but " +
                                  recipe_item_key(key, 0) +
                                  (given == 0 ? " gives " : " gives no ") + targets_name +
                                  ": in a list, every set gives them or none does");
        if (given != 0 && given != count)
            throw RecipeError(child(set, targets_name), "has " + std::to_string(given) +
                                                            " entries but " + child(set, list) +
                                                            " has " + std::to_string(count));
        const size_t w = sets[k].weights.size();
        if (w != 0 && w != count)
            throw RecipeError(child(set, "weights"), std::to_string(w) + " weights for " +
                                                         std::to_string(count) + " " + list);
    }
}

// Merges a list of two or more sets into one with a weight per element: element k of set
// s weighs s.mu * s.weights[k] (s.mu without weights), and the merged mu is 1, so that
// the solver's mu * weight is that product exactly.
template <typename Set>
Set merge_sets(const std::vector<Set>& sets, const std::string& key, IndexSet Set::*elements,
               std::vector<Vec3> Set::*targets)
{
    Set merged = sets[0];
    merged.mu = 1;
    (merged.*elements).indices.clear();
    (merged.*targets).clear();
    merged.weights.clear();
    for (size_t s = 0; s < sets.size(); ++s)
    {
        const Set& set = sets[s];
        const std::vector<Index>& list = (set.*elements).indices;
        auto& into = (merged.*elements).indices;
        into.insert(into.end(), list.begin(), list.end());
        (merged.*targets)
            .insert((merged.*targets).end(), (set.*targets).begin(), (set.*targets).end());
        for (size_t k = 0; k < list.size(); ++k)
        {
            const Scalar w = set.weights.empty() ? set.mu : set.mu * set.weights[k];
            if (!std::isfinite(w))
                throw RecipeError(
                    recipe_item_key(child(recipe_item_key(key, s), "weights"), k),
                    "times " + child(recipe_item_key(key, s), "mu") + " is not finite");
            merged.weights.push_back(w);
        }
        merged.set_ends.push_back(into.size());
    }
    return merged;
}

// One set given as a list of one: kept as it is, with its key for messages ("soft[0]")
// when it lists its elements.
template <typename Set>
Set single_set(Set set, const IndexSet& elements)
{
    if (!elements.all)
        set.set_ends = {elements.indices.size()};
    return set;
}

void parse_lambda(const Json& j, Recipe& r)
{
    if (j.is_string())
    {
        if (j.get<std::string>() != "optimal")
            throw RecipeError("lambda", "must be a number > 0 or \"optimal\"");
        r.optimal_step = true;
        return;
    }
    r.lambda = step_length(j, "lambda");
    r.optimal_step = false;
}

SoftVertices soft_set(const Json& s, const std::string& key)
{
    expect_object(s, key, {"vertices", "mu", "targets", "weights"});
    if (!s.contains("vertices"))
        throw RecipeError(child(key, "vertices"), "is required");
    SoftVertices soft;
    soft.vertices = index_set(s["vertices"], child(key, "vertices"));
    if (s.contains("mu"))
        soft.mu = weight(s["mu"], child(key, "mu"));
    if (s.contains("targets"))
        soft.targets = points(s["targets"], child(key, "targets"));
    if (s.contains("weights"))
        soft.weights = weights(s["weights"], child(key, "weights"));
    return soft;
}

SoftVertices parse_soft(const Json& j)
{
    const std::vector<SoftVertices> sets = sets_of<SoftVertices>(j, "soft", soft_set);
    if (j.is_object())
        return sets[0];
    if (sets.size() == 1)
        return single_set(sets[0], sets[0].vertices);
    check_set_list(sets, "soft", "vertices", &SoftVertices::vertices, "targets",
                   &SoftVertices::targets);
    return merge_sets(sets, "soft", &SoftVertices::vertices, &SoftVertices::targets);
}

const char* denominator_name(CentroidDenominator d)
{
    return d == CentroidDenominator::Paper ? "paper" : "exact";
}

CentroidConstraints centroid_set(const Json& s, const std::string& key)
{
    expect_object(s, key, {"faces", "mu", "targets", "denominator", "weights"});
    if (!s.contains("faces"))
        throw RecipeError(child(key, "faces"), "is required");
    CentroidConstraints c;
    c.faces = index_set(s["faces"], child(key, "faces"));
    if (s.contains("mu"))
        c.mu = weight(s["mu"], child(key, "mu"));
    if (s.contains("targets"))
        c.targets = points(s["targets"], child(key, "targets"));
    if (s.contains("denominator"))
        c.denominator = choice(s["denominator"], child(key, "denominator"), {"paper", "exact"}) == 0
                            ? CentroidDenominator::Paper
                            : CentroidDenominator::Exact;
    if (s.contains("weights"))
        c.weights = weights(s["weights"], child(key, "weights"));
    return c;
}

CentroidConstraints parse_centroid(const Json& j)
{
    const std::vector<CentroidConstraints> sets =
        sets_of<CentroidConstraints>(j, "centroid", centroid_set);
    if (j.is_object())
        return sets[0];
    if (sets.size() == 1)
        return single_set(sets[0], sets[0].faces);
    check_set_list(sets, "centroid", "faces", &CentroidConstraints::faces, "targets",
                   &CentroidConstraints::targets);
    // One term, one denominator: every set must name the same (omitted: "paper").
    for (size_t k = 1; k < sets.size(); ++k)
        if (sets[k].denominator != sets[0].denominator)
            throw RecipeError(child(recipe_item_key("centroid", k), "denominator"),
                              std::string("\"") + denominator_name(sets[k].denominator) +
                                  "\" differs from centroid[0]'s \"" +
                                  denominator_name(sets[0].denominator) +
                                  "\" (the sets of a list share one denominator)");
    return merge_sets(sets, "centroid", &CentroidConstraints::faces, &CentroidConstraints::targets);
}

const char* source_name(NormalSource source)
{
    switch (source)
    {
        case NormalSource::Initial:
            return "\"initial\"";
        case NormalSource::Smoothed:
            return "\"smoothed\"";
        case NormalSource::Custom:
            break;
    }
    return "given normals";
}

NormalConstraints normal_set(const Json& s, const std::string& key, bool has_smoothing)
{
    expect_object(s, key, {"faces", "mu", "normals", "weights"});
    if (!s.contains("faces"))
        throw RecipeError(child(key, "faces"), "is required");
    NormalConstraints n;
    n.faces = index_set(s["faces"], child(key, "faces"));
    if (s.contains("mu"))
        n.mu = weight(s["mu"], child(key, "mu"));
    if (s.contains("normals"))
    {
        const Json& v = s["normals"];
        if (v == "initial")
            n.source = NormalSource::Initial;
        else if (v == "smoothed")
            n.source = NormalSource::Smoothed;
        else if (v.is_array())
        {
            n.source = NormalSource::Custom;
            n.normals = points(v, child(key, "normals"));
        }
        else
            throw RecipeError(child(key, "normals"),
                              "must be \"initial\", \"smoothed\" or an array of [x, y, z]");
    }
    else if (has_smoothing)
        n.source = NormalSource::Smoothed;
    if (s.contains("weights"))
        n.weights = weights(s["weights"], child(key, "weights"));
    return n;
}

NormalConstraints parse_normal(const Json& j, bool has_smoothing)
{
    const std::vector<NormalConstraints> sets = sets_of<NormalConstraints>(
        j, "normal",
        [&](const Json& s, const std::string& key) { return normal_set(s, key, has_smoothing); });
    if (j.is_object())
        return sets[0];
    if (sets.size() == 1)
        return single_set(sets[0], sets[0].faces);
    // One term, one source of normals: every set must name the same.
    for (size_t k = 1; k < sets.size(); ++k)
        if (sets[k].source != sets[0].source)
            throw RecipeError(child(recipe_item_key("normal", k), "normals"),
                              std::string(source_name(sets[k].source)) +
                                  " differs from normal[0]'s " + source_name(sets[0].source) +
                                  " (the sets of a list take their normals from one source)");
    check_set_list(sets, "normal", "faces", &NormalConstraints::faces, "normals",
                   &NormalConstraints::normals);
    return merge_sets(sets, "normal", &NormalConstraints::faces, &NormalConstraints::normals);
}

Recipe parse_recipe_json(const Json& j)
{
    Recipe r;
    expect_object(
        j, "", {"description",      "editor", "iterations", "lambda", "tolerance", "method",
                "taubin_mu",        "region", "hard",       "soft",   "centroid",  "normal",
                "normal_smoothing", "joint",  "bending",    "volume", "falloff",   "prevent_flips",
                "factor_budget_mb", "time"});
    if (j.contains("editor") && !j["editor"].is_object())
        throw RecipeError("editor", "must be an object (the editor's sets and view)");
    if (j.contains("description"))
    {
        if (!j["description"].is_string())
            throw RecipeError("description",
                              "must be a string (got " + describe(j["description"]) + ")");
        r.description = j["description"].get<std::string>();
    }
    if (j.contains("iterations"))
        r.iterations = count(j["iterations"], "iterations");
    if (j.contains("lambda"))
        parse_lambda(j["lambda"], r);
    if (j.contains("tolerance"))
        r.tolerance = weight(j["tolerance"], "tolerance");
    if (j.contains("method"))
    {
        constexpr Method methods[] = {Method::Jacobi, Method::GradientDescent,   Method::Taubin,
                                      Method::Direct, Method::ConjugateGradient, Method::Implicit};
        r.method =
            methods[choice(j["method"], "method",
                           {"jacobi", "gradient_descent", "taubin", "direct", "cg", "implicit"})];
    }
    if (j.contains("time"))
        r.time = number(j["time"], "time");
    if (j.contains("factor_budget_mb"))
        r.factor_budget_mb = weight(j["factor_budget_mb"], "factor_budget_mb");
    if (j.contains("taubin_mu"))
        r.taubin_mu = number(j["taubin_mu"], "taubin_mu");
    if (j.contains("region"))
    {
        const Json& s = j["region"];
        expect_object(s, "region", {"vertices", "faces"});
        if (!s.contains("vertices") && !s.contains("faces"))
            throw RecipeError("region", "needs \"vertices\" or \"faces\"");
        Region region;
        if (s.contains("vertices"))
            region.vertices = indices(s["vertices"], "region.vertices");
        if (s.contains("faces"))
            region.faces = indices(s["faces"], "region.faces");
        r.region = std::move(region);
    }
    if (j.contains("hard"))
    {
        const Json& s = j["hard"];
        expect_object(s, "hard", {"vertices", "targets"});
        if (!s.contains("vertices"))
            throw RecipeError("hard.vertices", "is required");
        HardVertices hard;
        hard.vertices = indices(s["vertices"], "hard.vertices");
        if (s.contains("targets"))
            hard.targets = points(s["targets"], "hard.targets");
        r.hard = std::move(hard);
    }
    if (j.contains("soft"))
        r.soft = parse_soft(j["soft"]);
    if (j.contains("centroid"))
        r.centroid = parse_centroid(j["centroid"]);
    if (j.contains("normal"))
        r.normal = parse_normal(j["normal"], j.contains("normal_smoothing"));
    if (j.contains("normal_smoothing"))
    {
        const Json& s = j["normal_smoothing"];
        expect_object(s, "normal_smoothing",
                      {"iterations", "lambda", "hard", "soft", "bilateral", "strength",
                       "iterations_per_noise"});
        NormalSmoothing ns;
        if (s.contains("iterations") && s["iterations"].is_string())
        {
            if (s["iterations"] != "auto")
                throw RecipeError(
                    "normal_smoothing.iterations",
                    "must be a count or \"auto\" (got " + s["iterations"].dump() + ")");
            ns.adaptive = AdaptiveIterations{};
        }
        else if (s.contains("iterations"))
            ns.iterations = count(s["iterations"], "normal_smoothing.iterations");
        for (const char* key : {"strength", "iterations_per_noise"})
            if (s.contains(key) && !ns.adaptive)
                throw RecipeError(std::string("normal_smoothing.") + key,
                                  "needs \"iterations\": \"auto\" (it scales the iterations "
                                  "taken from the noise in the mesh)");
        if (s.contains("strength"))
            ns.adaptive->strength = weight(s["strength"], "normal_smoothing.strength");
        if (s.contains("iterations_per_noise"))
            ns.adaptive->per_noise =
                weight(s["iterations_per_noise"], "normal_smoothing.iterations_per_noise");
        if (s.contains("lambda"))
            ns.lambda = step_length(s["lambda"], "normal_smoothing.lambda");
        if (s.contains("hard"))
        {
            const Json& h = s["hard"];
            expect_object(h, "normal_smoothing.hard", {"faces", "normals"});
            if (!h.contains("faces"))
                throw RecipeError("normal_smoothing.hard.faces", "is required");
            ns.hard.faces = indices(h["faces"], "normal_smoothing.hard.faces");
            if (h.contains("normals"))
                ns.hard.normals = points(h["normals"], "normal_smoothing.hard.normals");
        }
        if (s.contains("soft"))
        {
            const Json& h = s["soft"];
            expect_object(h, "normal_smoothing.soft", {"faces", "mu", "normals", "weights"});
            if (!h.contains("faces"))
                throw RecipeError("normal_smoothing.soft.faces", "is required");
            ns.soft.faces = indices(h["faces"], "normal_smoothing.soft.faces");
            if (h.contains("mu"))
                ns.soft.mu = weight(h["mu"], "normal_smoothing.soft.mu");
            if (h.contains("normals"))
                ns.soft.normals = points(h["normals"], "normal_smoothing.soft.normals");
            if (h.contains("weights"))
                ns.soft.weights = weights(h["weights"], "normal_smoothing.soft.weights");
        }
        if (s.contains("bilateral"))
            ns.bilateral = parse_bilateral(s["bilateral"], "normal_smoothing.bilateral");
        r.normal_smoothing = std::move(ns);
    }
    if (j.contains("joint"))
    {
        const Json& s = j["joint"];
        expect_object(s, "joint", {"gamma"});
        Joint joint;
        if (s.contains("gamma"))
            joint.gamma = weight(s["gamma"], "joint.gamma");
        r.joint = joint;
    }
    if (j.contains("bending"))
        r.bending = parse_bending(j["bending"], "bending");
    if (j.contains("volume"))
    {
        const Json& s = j["volume"];
        expect_object(s, "volume", {"open", "components"});
        KeepVolume volume;
        if (s.contains("open"))
            volume.open = choice(s["open"], "volume.open", {"capped", "none"}) == 0
                              ? OpenVolume::Capped
                              : OpenVolume::None;
        if (s.contains("components"))
            volume.free_components_only =
                choice(s["components"], "volume.components", {"all", "free"}) == 1;
        r.volume = volume;
    }
    if (j.contains("prevent_flips"))
    {
        if (!j["prevent_flips"].is_boolean())
            throw RecipeError("prevent_flips", "must be true or false");
        r.prevent_flips = j["prevent_flips"].get<bool>();
    }
    if (j.contains("falloff"))
        r.falloff = parse_falloff(j["falloff"], "falloff");
    return r;
}

Json points_json(const std::vector<Vec3>& v)
{
    Json a = Json::array();
    for (const Vec3& p : v)
        a.push_back({p[0], p[1], p[2]});
    return a;
}

Json set_json(const IndexSet& s)
{
    return s.all ? Json("all") : index_list_json(s.indices);
}

} // namespace

std::vector<Index> parse_index_list(const Json& j, const std::string& key, std::int64_t& budget)
{
    if (!j.is_array())
        throw RecipeError(key, "must be an array of indices and [first, last] runs");
    const auto index = [&](const Json& v, const std::string& at) {
        const std::int64_t i = integer(v, at);
        if (i < 0 || i > kMaxElements)
            throw RecipeError(at, "index " + std::to_string(i) + " is out of range");
        return i;
    };
    const auto take = [&](std::int64_t n, const std::string& at) {
        if (n > budget)
            throw RecipeError(
                at, "lists more indices than a recipe may (" + std::to_string(budget) + " left)");
        budget -= n;
    };
    std::vector<Index> out;
    out.reserve(j.size());
    for (size_t k = 0; k < j.size(); ++k)
    {
        const std::string at = recipe_item_key(key, k);
        if (j[k].is_array())
        {
            if (j[k].size() != 2)
                throw RecipeError(at, "a run must be [first, last]");
            const std::int64_t first = index(j[k][0], at + "[0]");
            const std::int64_t last = index(j[k][1], at + "[1]");
            if (last < first)
                throw RecipeError(at, "a run's last index must not be below its first (got [" +
                                          std::to_string(first) + ", " + std::to_string(last) +
                                          "])");
            take(last - first + 1, at);
            for (std::int64_t i = first; i <= last; ++i)
                out.push_back(static_cast<Index>(i));
        }
        else
        {
            take(1, at);
            out.push_back(static_cast<Index>(index(j[k], at)));
        }
    }
    return out;
}

Json index_list_json(std::span<const Index> indices)
{
    Json out = Json::array();
    for (size_t k = 0; k < indices.size();)
    {
        size_t end = k + 1;
        while (end < indices.size() && indices[end] == indices[end - 1] + 1)
            ++end;
        if (end - k >= 3)
            out.push_back({indices[k], indices[end - 1]});
        else
            for (size_t m = k; m < end; ++m)
                out.push_back(indices[m]);
        k = end;
    }
    return out;
}

Recipe parse_recipe(std::string_view json_text, const std::string& name, const RecipeLimits& limits)
{
    listed_left = limits.max_listed;
    nlohmann::json j;
    try
    {
        j = Json::parse(json_text.begin(), json_text.end());
    }
    catch (const Json::parse_error& e)
    {
        throw json_syntax_error(name, e.what());
    }
    catch (const Json::exception& e)
    {
        // e.g. a number too large for a double: "number overflow parsing '1e400'".
        const std::string what = e.what();
        const auto close = what.find("] ");
        throw InvalidInputError("'" + name + "': not valid JSON: " +
                                (close == std::string::npos ? what : what.substr(close + 2)));
    }
    try
    {
        return parse_recipe_json(j);
    }
    catch (const RecipeError& e)
    {
        throw RecipeError(e.key(), e.message(), name);
    }
}

Recipe read_recipe(const std::string& path)
{
    return parse_recipe(io::read_file(path), path);
}

nlohmann::json recipe_to_json(const Recipe& r)
{
    Json j;
    if (!r.description.empty())
        j["description"] = r.description;
    j["iterations"] = r.iterations;
    j["lambda"] = r.optimal_step ? Json("optimal") : Json(r.lambda);
    j["tolerance"] = r.tolerance;
    j["method"] = r.method == Method::Jacobi              ? "jacobi"
                  : r.method == Method::GradientDescent   ? "gradient_descent"
                  : r.method == Method::Direct            ? "direct"
                  : r.method == Method::ConjugateGradient ? "cg"
                  : r.method == Method::Implicit          ? "implicit"
                                                          : "taubin";
    if (r.method == Method::Implicit)
        j["time"] = r.time;
    if (r.factor_budget_mb > 0)
        j["factor_budget_mb"] = r.factor_budget_mb;
    if (r.method == Method::Taubin)
        j["taubin_mu"] = r.taubin_mu;
    if (r.region)
    {
        Json s = Json::object();
        if (!r.region->vertices.empty() || r.region->faces.empty())
            s["vertices"] = index_list_json(r.region->vertices);
        if (!r.region->faces.empty())
            s["faces"] = index_list_json(r.region->faces);
        j["region"] = s;
    }
    if (r.hard)
    {
        j["hard"] = {{"vertices", index_list_json(r.hard->vertices)}};
        if (!r.hard->targets.empty())
            j["hard"]["targets"] = points_json(r.hard->targets);
    }
    if (r.soft)
    {
        j["soft"] = {{"vertices", set_json(r.soft->vertices)}, {"mu", r.soft->mu}};
        if (!r.soft->targets.empty())
            j["soft"]["targets"] = points_json(r.soft->targets);
        if (!r.soft->weights.empty())
            j["soft"]["weights"] = r.soft->weights;
    }
    if (r.centroid)
    {
        j["centroid"] = {
            {"faces", set_json(r.centroid->faces)},
            {"mu", r.centroid->mu},
            {"denominator",
             r.centroid->denominator == CentroidDenominator::Paper ? "paper" : "exact"}};
        if (!r.centroid->targets.empty())
            j["centroid"]["targets"] = points_json(r.centroid->targets);
        if (!r.centroid->weights.empty())
            j["centroid"]["weights"] = r.centroid->weights;
    }
    if (r.normal)
    {
        j["normal"] = {{"faces", set_json(r.normal->faces)}, {"mu", r.normal->mu}};
        switch (r.normal->source)
        {
            case NormalSource::Initial:
                j["normal"]["normals"] = "initial";
                break;
            case NormalSource::Smoothed:
                j["normal"]["normals"] = "smoothed";
                break;
            case NormalSource::Custom:
                j["normal"]["normals"] = points_json(r.normal->normals);
                break;
        }
        if (!r.normal->weights.empty())
            j["normal"]["weights"] = r.normal->weights;
    }
    if (r.normal_smoothing)
    {
        const NormalSmoothing& ns = *r.normal_smoothing;
        Json s = {{"iterations", ns.iterations}, {"lambda", ns.lambda}};
        if (ns.adaptive)
        {
            s["iterations"] = "auto";
            s["strength"] = ns.adaptive->strength;
            s["iterations_per_noise"] = ns.adaptive->per_noise;
        }
        if (!ns.hard.faces.empty())
        {
            s["hard"] = {{"faces", index_list_json(ns.hard.faces)}};
            if (!ns.hard.normals.empty())
                s["hard"]["normals"] = points_json(ns.hard.normals);
        }
        if (!ns.soft.faces.empty())
        {
            s["soft"] = {{"faces", index_list_json(ns.soft.faces)}, {"mu", ns.soft.mu}};
            if (!ns.soft.normals.empty())
                s["soft"]["normals"] = points_json(ns.soft.normals);
            if (!ns.soft.weights.empty())
                s["soft"]["weights"] = ns.soft.weights;
        }
        if (ns.bilateral)
            s["bilateral"] = bilateral_json(*ns.bilateral);
        j["normal_smoothing"] = s;
    }
    if (r.joint)
        j["joint"] = {{"gamma", r.joint->gamma}};
    if (r.bending)
        j["bending"] = bending_json(*r.bending);
    if (r.volume)
    {
        j["volume"] = Json::object();
        if (r.volume->open != OpenVolume::Capped)
            j["volume"]["open"] = "none";
        if (r.volume->free_components_only)
            j["volume"]["components"] = "free";
    }
    if (r.prevent_flips)
        j["prevent_flips"] = true;
    if (r.falloff)
        j["falloff"] = falloff_json(*r.falloff);
    return j;
}

BilateralWeights parse_bilateral(const Json& s, const std::string& key)
{
    expect_object(s, key,
                  {"sigma_s", "sigma_r", "noise_scale", "reweight_every", "neighbors", "guidance"});
    BilateralWeights b;
    if (s.contains("sigma_s"))
        b.sigma_s = step_length(s["sigma_s"], child(key, "sigma_s"));
    if (s.contains("sigma_r"))
        b.sigma_r = step_length(s["sigma_r"], child(key, "sigma_r"));
    if (s.contains("noise_scale"))
        b.noise_scale = weight(s["noise_scale"], child(key, "noise_scale"));
    if (s.contains("reweight_every"))
    {
        b.reweight_every = count(s["reweight_every"], child(key, "reweight_every"));
        if (b.reweight_every < 1)
            throw RecipeError(child(key, "reweight_every"), "must be >= 1 (got 0)");
    }
    if (s.contains("neighbors"))
        b.neighbors = choice(s["neighbors"], child(key, "neighbors"), {"edge", "vertex"}) == 0
                          ? FaceNeighborhood::Edge
                          : FaceNeighborhood::Vertex;
    if (s.contains("guidance"))
        b.guided = choice(s["guidance"], child(key, "guidance"), {"none", "patch"}) == 1;
    return b;
}

Bending parse_bending(const Json& s, const std::string& key)
{
    expect_object(s, key, {"mu", "membrane"});
    Bending b;
    if (s.contains("mu"))
        b.mu = weight(s["mu"], key + ".mu");
    if (s.contains("membrane"))
        b.membrane = weight(s["membrane"], key + ".membrane");
    return b;
}

Json bending_json(const Bending& b)
{
    return {{"mu", b.mu}, {"membrane", b.membrane}};
}

Falloff parse_falloff(const Json& s, const std::string& key)
{
    expect_object(s, key, {"radius", "units", "curve", "mu", "around"});
    Falloff f;
    if (s.contains("radius"))
        f.radius = weight(s["radius"], child(key, "radius"));
    if (s.contains("units"))
        f.radius_in_edge_lengths =
            choice(s["units"], child(key, "units"), {"edge_lengths", "mesh"}) == 0;
    if (s.contains("curve"))
    {
        const std::optional<FalloffCurve> curve =
            s["curve"].is_string() ? falloff_curve_named(s["curve"].get<std::string>())
                                   : std::nullopt;
        if (curve)
            f.curve = *curve;
        else
            throw RecipeError(child(key, "curve"),
                              "must be \"smooth\", \"sphere\", \"root\", "
                              "\"linear\", \"sharp\" or \"constant\"");
    }
    if (s.contains("mu"))
        f.mu = weight(s["mu"], child(key, "mu"));
    if (s.contains("around"))
    {
        const Json& a = s["around"];
        if (!a.is_array() || a.empty())
            throw RecipeError(child(key, "around"),
                              "must be a non-empty list of \"border\" and \"pins\"");
        f.border = f.pins = false;
        for (size_t k = 0; k < a.size(); ++k)
            (choice(a[k], recipe_item_key(child(key, "around"), k), {"border", "pins"}) == 0
                 ? f.border
                 : f.pins) = true;
    }
    return f;
}

Json bilateral_json(const BilateralWeights& b)
{
    Json j = {{"sigma_s", b.sigma_s},
              {"sigma_r", b.sigma_r},
              {"noise_scale", b.noise_scale},
              {"reweight_every", b.reweight_every},
              {"neighbors", b.neighbors == FaceNeighborhood::Edge ? "edge" : "vertex"}};
    // Written when not the default, so recipes written before it read back the same.
    if (b.guided)
        j["guidance"] = "patch";
    return j;
}

Json falloff_json(const Falloff& f)
{
    const std::string curve(falloff_curve_name(f.curve));
    Json around = Json::array();
    if (f.border)
        around.push_back("border");
    if (f.pins)
        around.push_back("pins");
    return {{"radius", f.radius},
            {"units", f.radius_in_edge_lengths ? "edge_lengths" : "mesh"},
            {"curve", curve},
            {"mu", f.mu},
            {"around", around}};
}

} // namespace meshfair
