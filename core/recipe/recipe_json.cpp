// SPDX-License-Identifier: MIT
// Copyright 2026 the MeshFair authors.
#include "core/recipe/recipe_json.h"

#include <cmath>
#include <initializer_list>
#include <limits>

#include "core/errors.h"
#include "core/io/io.h"

namespace meshfair {

namespace {

using Json = nlohmann::json;

std::string child(const std::string& key, const std::string& name)
{
    return key.empty() ? name : key + "." + name;
}

std::string item(const std::string& key, size_t k)
{
    return key + "[" + std::to_string(k) + "]";
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
            throw RecipeError(child(key, name), "unknown key (allowed here: " + list + ")");
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

std::vector<Index> indices(const Json& j, const std::string& key)
{
    if (!j.is_array())
        throw RecipeError(key, "must be an array of indices");
    std::vector<Index> out;
    out.reserve(j.size());
    for (size_t k = 0; k < j.size(); ++k)
    {
        const std::int64_t v = integer(j[k], item(key, k));
        if (v < 0 || v > kMaxElements)
            throw RecipeError(item(key, k), "index " + std::to_string(v) + " is out of range");
        out.push_back(static_cast<Index>(v));
    }
    return out;
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
            throw RecipeError(item(key, k), "must be an [x, y, z] triple");
        Vec3 v;
        for (size_t a = 0; a < 3; ++a)
            v[a] = number(p[a], item(item(key, k), a));
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

Recipe parse_recipe_json(const Json& j)
{
    Recipe r;
    expect_object(j, "",
                  {"iterations", "lambda", "tolerance", "method", "region", "hard", "soft",
                   "centroid", "normal", "normal_smoothing", "joint"});
    if (j.contains("iterations"))
        r.iterations = count(j["iterations"], "iterations");
    if (j.contains("lambda"))
        parse_lambda(j["lambda"], r);
    if (j.contains("tolerance"))
        r.tolerance = weight(j["tolerance"], "tolerance");
    if (j.contains("method"))
    {
        const Json& m = j["method"];
        if (m == "jacobi")
            r.method = Method::Jacobi;
        else if (m == "gradient_descent")
            r.method = Method::GradientDescent;
        else
            throw RecipeError("method", "must be \"jacobi\" or \"gradient_descent\"");
    }
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
    {
        const Json& s = j["soft"];
        expect_object(s, "soft", {"vertices", "mu", "targets"});
        if (!s.contains("vertices"))
            throw RecipeError("soft.vertices", "is required");
        SoftVertices soft;
        soft.vertices = index_set(s["vertices"], "soft.vertices");
        if (s.contains("mu"))
            soft.mu = weight(s["mu"], "soft.mu");
        if (s.contains("targets"))
            soft.targets = points(s["targets"], "soft.targets");
        r.soft = std::move(soft);
    }
    if (j.contains("centroid"))
    {
        const Json& s = j["centroid"];
        expect_object(s, "centroid", {"faces", "mu", "targets", "denominator"});
        if (!s.contains("faces"))
            throw RecipeError("centroid.faces", "is required");
        CentroidConstraints c;
        c.faces = index_set(s["faces"], "centroid.faces");
        if (s.contains("mu"))
            c.mu = weight(s["mu"], "centroid.mu");
        if (s.contains("targets"))
            c.targets = points(s["targets"], "centroid.targets");
        if (s.contains("denominator"))
        {
            if (s["denominator"] == "paper")
                c.denominator = CentroidDenominator::Paper;
            else if (s["denominator"] == "exact")
                c.denominator = CentroidDenominator::Exact;
            else
                throw RecipeError("centroid.denominator", "must be \"paper\" or \"exact\"");
        }
        r.centroid = std::move(c);
    }
    if (j.contains("normal"))
    {
        const Json& s = j["normal"];
        expect_object(s, "normal", {"faces", "mu", "normals"});
        if (!s.contains("faces"))
            throw RecipeError("normal.faces", "is required");
        NormalConstraints n;
        n.faces = index_set(s["faces"], "normal.faces");
        if (s.contains("mu"))
            n.mu = weight(s["mu"], "normal.mu");
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
                n.normals = points(v, "normal.normals");
            }
            else
                throw RecipeError("normal.normals",
                                  "must be \"initial\", \"smoothed\" or an array of [x, y, z]");
        }
        else if (j.contains("normal_smoothing"))
            n.source = NormalSource::Smoothed;
        r.normal = std::move(n);
    }
    if (j.contains("normal_smoothing"))
    {
        const Json& s = j["normal_smoothing"];
        expect_object(s, "normal_smoothing", {"iterations", "lambda", "hard", "soft"});
        NormalSmoothing ns;
        if (s.contains("iterations"))
            ns.iterations = count(s["iterations"], "normal_smoothing.iterations");
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
            expect_object(h, "normal_smoothing.soft", {"faces", "mu", "normals"});
            if (!h.contains("faces"))
                throw RecipeError("normal_smoothing.soft.faces", "is required");
            ns.soft.faces = indices(h["faces"], "normal_smoothing.soft.faces");
            if (h.contains("mu"))
                ns.soft.mu = weight(h["mu"], "normal_smoothing.soft.mu");
            if (h.contains("normals"))
                ns.soft.normals = points(h["normals"], "normal_smoothing.soft.normals");
        }
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
    return s.all ? Json("all") : Json(s.indices);
}

} // namespace

InvalidInputError json_syntax_error(const std::string& name, const std::string& what)
{
    // what is "[json.exception.parse_error.101] parse error at line L, column C: why".
    const auto at = what.find(" at line ");
    const auto why = what.find(": ", at == std::string::npos ? 0 : at);
    if (at == std::string::npos || why == std::string::npos)
        return InvalidInputError("'" + name + "': not valid JSON: " + what);
    std::string place = what.substr(at + 9, why - at - 9); // "L, column C"
    const auto comma = place.find(", column ");
    if (comma != std::string::npos)
        place = place.substr(0, comma) + ":" + place.substr(comma + 9);
    return InvalidInputError("'" + name + "':" + place +
                             ": not valid JSON: " + what.substr(why + 2));
}

Recipe parse_recipe(std::string_view json_text, const std::string& name)
{
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
    j["iterations"] = r.iterations;
    j["lambda"] = r.optimal_step ? Json("optimal") : Json(r.lambda);
    j["tolerance"] = r.tolerance;
    j["method"] = r.method == Method::Jacobi ? "jacobi" : "gradient_descent";
    if (r.region)
    {
        Json s = Json::object();
        if (!r.region->vertices.empty() || r.region->faces.empty())
            s["vertices"] = r.region->vertices;
        if (!r.region->faces.empty())
            s["faces"] = r.region->faces;
        j["region"] = s;
    }
    if (r.hard)
    {
        j["hard"] = {{"vertices", r.hard->vertices}};
        if (!r.hard->targets.empty())
            j["hard"]["targets"] = points_json(r.hard->targets);
    }
    if (r.soft)
    {
        j["soft"] = {{"vertices", set_json(r.soft->vertices)}, {"mu", r.soft->mu}};
        if (!r.soft->targets.empty())
            j["soft"]["targets"] = points_json(r.soft->targets);
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
    }
    if (r.normal_smoothing)
    {
        const NormalSmoothing& ns = *r.normal_smoothing;
        Json s = {{"iterations", ns.iterations}, {"lambda", ns.lambda}};
        if (!ns.hard.faces.empty())
        {
            s["hard"] = {{"faces", ns.hard.faces}};
            if (!ns.hard.normals.empty())
                s["hard"]["normals"] = points_json(ns.hard.normals);
        }
        if (!ns.soft.faces.empty())
        {
            s["soft"] = {{"faces", ns.soft.faces}, {"mu", ns.soft.mu}};
            if (!ns.soft.normals.empty())
                s["soft"]["normals"] = points_json(ns.soft.normals);
        }
        j["normal_smoothing"] = s;
    }
    if (r.joint)
        j["joint"] = {{"gamma", r.joint->gamma}};
    return j;
}

} // namespace meshfair
