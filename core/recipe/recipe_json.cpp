// SPDX-License-Identifier: MIT
// Copyright 2026 the MeshFair authors.
#include "core/recipe/recipe_json.h"

#include <cmath>
#include <limits>
#include <string_view>

#include "core/errors.h"
#include "core/io/io.h"

namespace meshfair {

namespace {

using Json = nlohmann::json;

constexpr double kUnbounded = std::numeric_limits<double>::infinity();

std::string child(const std::string& key, const std::string& name)
{
    return key + "." + name;
}

Scalar weight(const CheckedJson& j)
{
    return j.number(0, kUnbounded);
}

int count(const CheckedJson& j)
{
    return static_cast<int>(j.integer(0, std::numeric_limits<int>::max()));
}

// The indices the recipe being parsed may still list (RecipeLimits::max_listed): set by
// parse_recipe for its thread, taken from by every index list.
thread_local std::int64_t listed_left = RecipeLimits{}.max_listed;

std::vector<Index> indices(const CheckedJson& j)
{
    return parse_index_list(j, listed_left);
}

IndexSet index_set(const CheckedJson& j)
{
    IndexSet s;
    if (j.is_string())
    {
        if (j.text() != "all")
            j.fail("must be \"all\" or an array of indices");
        s.all = true;
        return s;
    }
    s.indices = indices(j);
    return s;
}

std::vector<Vec3> points(const CheckedJson& j)
{
    if (!j.is_array())
        j.fail("must be an array of [x, y, z] triples");
    std::vector<Vec3> out;
    out.reserve(j.size());
    for (const CheckedJson& p : j.elements())
        out.push_back(p.vec3());
    return out;
}

std::vector<Scalar> weights(const CheckedJson& j)
{
    if (!j.is_array())
        j.fail("must be an array of numbers >= 0");
    return j.numbers(0, kUnbounded);
}

// The sets a section gives: one object, or a non-empty array of them (each parsed by
// parse_one, named by its path, "soft[1]").
template <typename Set, typename ParseOne>
std::vector<Set> sets_of(const CheckedJson& j, ParseOne parse_one)
{
    if (j.is_object())
        return {parse_one(j)};
    if (!j.is_array())
        j.fail("must be an object or an array of objects");
    if (j.size() == 0)
        j.fail("must hold at least one set (leave the section out for none)");
    std::vector<Set> sets;
    sets.reserve(j.size());
    for (const CheckedJson& s : j.elements())
        sets.push_back(parse_one(s));
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

void parse_lambda(const CheckedJson& j, Recipe& r)
{
    if (j.is_string())
    {
        if (j.text() != "optimal")
            j.fail("must be a number > 0 or \"optimal\"");
        r.optimal_step = true;
        return;
    }
    r.lambda = j.positive();
    r.optimal_step = false;
}

SoftVertices soft_set(const CheckedJson& s)
{
    s.only_keys({"vertices", "mu", "targets", "weights"});
    SoftVertices soft;
    soft.vertices = index_set(s["vertices"]);
    if (const auto mu = s.find("mu"))
        soft.mu = weight(*mu);
    if (const auto targets = s.find("targets"))
        soft.targets = points(*targets);
    if (const auto w = s.find("weights"))
        soft.weights = weights(*w);
    return soft;
}

SoftVertices parse_soft(const CheckedJson& j)
{
    const std::vector<SoftVertices> sets = sets_of<SoftVertices>(j, soft_set);
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

CentroidConstraints centroid_set(const CheckedJson& s)
{
    s.only_keys({"faces", "mu", "targets", "denominator", "weights"});
    CentroidConstraints c;
    c.faces = index_set(s["faces"]);
    if (const auto mu = s.find("mu"))
        c.mu = weight(*mu);
    if (const auto targets = s.find("targets"))
        c.targets = points(*targets);
    if (const auto d = s.find("denominator"))
        c.denominator = d->choice<CentroidDenominator>(
            {{"paper", CentroidDenominator::Paper}, {"exact", CentroidDenominator::Exact}});
    if (const auto w = s.find("weights"))
        c.weights = weights(*w);
    return c;
}

CentroidConstraints parse_centroid(const CheckedJson& j)
{
    const std::vector<CentroidConstraints> sets = sets_of<CentroidConstraints>(j, centroid_set);
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

NormalConstraints normal_set(const CheckedJson& s, bool has_smoothing)
{
    s.only_keys({"faces", "mu", "normals", "weights"});
    NormalConstraints n;
    n.faces = index_set(s["faces"]);
    if (const auto mu = s.find("mu"))
        n.mu = weight(*mu);
    if (const auto v = s.find("normals"))
    {
        if (v->raw() == "initial")
            n.source = NormalSource::Initial;
        else if (v->raw() == "smoothed")
            n.source = NormalSource::Smoothed;
        else if (v->is_array())
        {
            n.source = NormalSource::Custom;
            n.normals = points(*v);
        }
        else
            v->fail("must be \"initial\", \"smoothed\" or an array of [x, y, z]");
    }
    else if (has_smoothing)
        n.source = NormalSource::Smoothed;
    if (const auto w = s.find("weights"))
        n.weights = weights(*w);
    return n;
}

NormalConstraints parse_normal(const CheckedJson& j, bool has_smoothing)
{
    const std::vector<NormalConstraints> sets = sets_of<NormalConstraints>(
        j, [&](const CheckedJson& s) { return normal_set(s, has_smoothing); });
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

// A "normal_smoothing" section's "hard" or "soft" object: faces required, the rest as given.
void smoothing_faces(const CheckedJson& h, std::vector<Index>& faces, std::vector<Vec3>& normals)
{
    faces = indices(h["faces"]);
    if (const auto v = h.find("normals"))
        normals = points(*v);
}

NormalSmoothing parse_normal_smoothing(const CheckedJson& s)
{
    s.only_keys(
        {"iterations", "lambda", "hard", "soft", "bilateral", "strength", "iterations_per_noise"});
    NormalSmoothing ns;
    if (const auto it = s.find("iterations"))
    {
        if (!it->is_string())
            ns.iterations = count(*it);
        else if (it->raw() != "auto")
            it->fail("must be a count or \"auto\" (got " + it->describe() + ")");
        else
            ns.adaptive = AdaptiveIterations{};
    }
    for (const char* key : {"strength", "iterations_per_noise"})
        if (s.has(key) && !ns.adaptive)
            s[key].fail(
                "needs \"iterations\": \"auto\" (it scales the iterations taken from the noise "
                "in the mesh)");
    if (const auto strength = s.find("strength"))
        ns.adaptive->strength = weight(*strength);
    if (const auto per_noise = s.find("iterations_per_noise"))
        ns.adaptive->per_noise = weight(*per_noise);
    if (const auto lambda = s.find("lambda"))
        ns.lambda = lambda->positive();
    if (const auto h = s.find("hard"))
    {
        h->only_keys({"faces", "normals"});
        smoothing_faces(*h, ns.hard.faces, ns.hard.normals);
    }
    if (const auto h = s.find("soft"))
    {
        h->only_keys({"faces", "mu", "normals", "weights"});
        smoothing_faces(*h, ns.soft.faces, ns.soft.normals);
        if (const auto mu = h->find("mu"))
            ns.soft.mu = weight(*mu);
        if (const auto w = h->find("weights"))
            ns.soft.weights = weights(*w);
    }
    if (const auto b = s.find("bilateral"))
        ns.bilateral = parse_bilateral(*b);
    return ns;
}

Recipe parse_recipe_json(const CheckedJson& j)
{
    Recipe r;
    j.only_keys({"description",      "editor", "iterations", "lambda", "tolerance", "method",
                 "taubin_mu",        "region", "hard",       "soft",   "centroid",  "normal",
                 "normal_smoothing", "joint",  "bending",    "volume", "falloff",   "prevent_flips",
                 "factor_budget_mb", "time"});
    if (j.has("editor") && !j["editor"].is_object())
        j["editor"].fail("must be an object (the editor's sets and view)");
    if (const auto d = j.find("description"))
        r.description = d->text();
    if (const auto it = j.find("iterations"))
        r.iterations = count(*it);
    if (const auto lambda = j.find("lambda"))
        parse_lambda(*lambda, r);
    if (const auto tolerance = j.find("tolerance"))
        r.tolerance = weight(*tolerance);
    if (const auto method = j.find("method"))
        r.method = method->choice<Method>({{"jacobi", Method::Jacobi},
                                           {"gradient_descent", Method::GradientDescent},
                                           {"taubin", Method::Taubin},
                                           {"direct", Method::Direct},
                                           {"cg", Method::ConjugateGradient},
                                           {"implicit", Method::Implicit}});
    if (const auto time = j.find("time"))
        r.time = time->number();
    if (const auto budget = j.find("factor_budget_mb"))
        r.factor_budget_mb = weight(*budget);
    if (const auto mu = j.find("taubin_mu"))
        r.taubin_mu = mu->number();
    if (const auto s = j.find("region"))
    {
        s->only_keys({"vertices", "faces"});
        if (!s->has("vertices") && !s->has("faces"))
            s->fail("needs \"vertices\" or \"faces\"");
        Region region;
        if (const auto v = s->find("vertices"))
            region.vertices = indices(*v);
        if (const auto f = s->find("faces"))
            region.faces = indices(*f);
        r.region = std::move(region);
    }
    if (const auto s = j.find("hard"))
    {
        s->only_keys({"vertices", "targets"});
        HardVertices hard;
        hard.vertices = indices((*s)["vertices"]);
        if (const auto targets = s->find("targets"))
            hard.targets = points(*targets);
        r.hard = std::move(hard);
    }
    if (const auto s = j.find("soft"))
        r.soft = parse_soft(*s);
    if (const auto s = j.find("centroid"))
        r.centroid = parse_centroid(*s);
    if (const auto s = j.find("normal"))
        r.normal = parse_normal(*s, j.has("normal_smoothing"));
    if (const auto s = j.find("normal_smoothing"))
        r.normal_smoothing = parse_normal_smoothing(*s);
    if (const auto s = j.find("joint"))
    {
        s->only_keys({"gamma"});
        Joint joint;
        if (const auto gamma = s->find("gamma"))
            joint.gamma = weight(*gamma);
        r.joint = joint;
    }
    if (const auto s = j.find("bending"))
        r.bending = parse_bending(*s);
    if (const auto s = j.find("volume"))
    {
        s->only_keys({"open", "components"});
        KeepVolume volume;
        if (const auto open = s->find("open"))
            volume.open = open->choice<OpenVolume>(
                {{"capped", OpenVolume::Capped}, {"none", OpenVolume::None}});
        if (const auto components = s->find("components"))
            volume.free_components_only = components->choice({"all", "free"}) == 1;
        r.volume = volume;
    }
    if (const auto flips = j.find("prevent_flips"))
        r.prevent_flips = flips->boolean();
    if (const auto s = j.find("falloff"))
        r.falloff = parse_falloff(*s);
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

std::vector<Index> parse_index_list(const CheckedJson& j, std::int64_t& budget)
{
    if (!j.is_array())
        j.fail("must be an array of indices and [first, last] runs");
    const auto take = [&](std::int64_t n, const CheckedJson& at) {
        if (n > budget)
            at.fail("lists more indices than a recipe may (" + std::to_string(budget) + " left)");
        budget -= n;
    };
    const auto index = [](const CheckedJson& v) {
        const std::int64_t i = v.integer();
        if (i < 0 || i > kMaxElements)
            v.fail("index " + std::to_string(i) + " is out of range");
        return i;
    };
    const Json& raw = j.raw();
    std::vector<Index> out;
    out.reserve(raw.size());
    for (size_t k = 0; k < raw.size(); ++k)
    {
        // A plain index read as it is: a list of a million makes no value of each.
        if (raw[k].is_number_unsigned() && raw[k].get<std::uint64_t>() <= kMaxElements &&
            budget > 0)
        {
            --budget;
            out.push_back(static_cast<Index>(raw[k].get<std::uint64_t>()));
            continue;
        }
        const CheckedJson at = j.at(k);
        if (!at.is_array())
        {
            take(1, at);
            out.push_back(static_cast<Index>(index(at)));
            continue;
        }
        if (at.size() != 2)
            at.fail("a run must be [first, last]");
        const std::int64_t first = index(at.at(0)), last = index(at.at(1));
        if (last < first)
            at.fail("a run's last index must not be below its first (got [" +
                    std::to_string(first) + ", " + std::to_string(last) + "])");
        take(last - first + 1, at);
        for (std::int64_t i = first; i <= last; ++i)
            out.push_back(static_cast<Index>(i));
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

Recipe parse_recipe(const CheckedJson& root, const RecipeLimits& limits)
{
    listed_left = limits.max_listed;
    try
    {
        return parse_recipe_json(root);
    }
    catch (const RecipeError& e)
    {
        // The rules across a section's sets throw without the file: named here.
        throw RecipeError(e.key(), e.message(), root.file());
    }
}

Recipe parse_recipe(std::string_view json_text, const std::string& name, const RecipeLimits& limits)
{
    return parse_recipe(CheckedJson::parse(json_text, name), limits);
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

BilateralWeights parse_bilateral(const CheckedJson& s)
{
    s.only_keys({"sigma_s", "sigma_r", "noise_scale", "reweight_every", "neighbors", "guidance"});
    BilateralWeights b;
    if (const auto sigma = s.find("sigma_s"))
        b.sigma_s = sigma->positive();
    if (const auto sigma = s.find("sigma_r"))
        b.sigma_r = sigma->positive();
    if (const auto scale = s.find("noise_scale"))
        b.noise_scale = weight(*scale);
    if (const auto every = s.find("reweight_every"))
    {
        b.reweight_every = count(*every);
        if (b.reweight_every < 1)
            every->fail("must be >= 1 (got 0)");
    }
    if (const auto n = s.find("neighbors"))
        b.neighbors = n->choice<FaceNeighborhood>(
            {{"edge", FaceNeighborhood::Edge}, {"vertex", FaceNeighborhood::Vertex}});
    if (const auto guidance = s.find("guidance"))
        b.guided = guidance->choice({"none", "patch"}) == 1;
    return b;
}

Bending parse_bending(const CheckedJson& s)
{
    s.only_keys({"mu", "membrane"});
    Bending b;
    if (const auto mu = s.find("mu"))
        b.mu = weight(*mu);
    if (const auto membrane = s.find("membrane"))
        b.membrane = weight(*membrane);
    return b;
}

Json bending_json(const Bending& b)
{
    return {{"mu", b.mu}, {"membrane", b.membrane}};
}

Falloff parse_falloff(const CheckedJson& s)
{
    s.only_keys({"radius", "units", "curve", "mu", "around"});
    Falloff f;
    if (const auto radius = s.find("radius"))
        f.radius = weight(*radius);
    if (const auto units = s.find("units"))
        f.radius_in_edge_lengths = units->choice({"edge_lengths", "mesh"}) == 0;
    if (const auto curve = s.find("curve"))
    {
        const std::optional<FalloffCurve> named =
            curve->is_string() ? falloff_curve_named(curve->text()) : std::nullopt;
        if (!named)
            curve->fail(
                "must be \"smooth\", \"sphere\", \"root\", \"linear\", \"sharp\" or \"constant\"");
        f.curve = *named;
    }
    if (const auto mu = s.find("mu"))
        f.mu = weight(*mu);
    if (const auto around = s.find("around"))
    {
        if (!around->is_array() || around->size() == 0)
            around->fail("must be a non-empty list of \"border\" and \"pins\"");
        f.border = f.pins = false;
        for (const CheckedJson& a : around->elements())
            (a.choice({"border", "pins"}) == 0 ? f.border : f.pins) = true;
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
