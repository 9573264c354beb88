// SPDX-License-Identifier: MIT
// Copyright 2026 the MeshFair authors.
#include "app/editor/script.h"

#include <algorithm>
#include <cmath>
#include <nlohmann/json.hpp>

#include "app/editor/heat_map.h"
#include "core/errors.h"
#include "core/io/io.h"
#include "core/recipe/recipe_json.h"

namespace meshfair::app {

namespace {

using Json = nlohmann::json;
using Kind = ScriptAction::Kind;

[[noreturn]] void fail(const std::string& name, const std::string& where, const std::string& why)
{
    throw InvalidInputError("'" + name + "': " + where + ": " + why);
}

struct Reader
{
    const std::string& name;
    std::string where;

    [[noreturn]] void bad(const std::string& key, const std::string& why) const
    {
        fail(name, where + "." + key, why);
    }
    std::string text(const Json& j, const std::string& key) const
    {
        if (!j.is_string())
            bad(key, "must be a string");
        return j.get<std::string>();
    }
    double number(const Json& j, const std::string& key, double lo, double hi) const
    {
        if (!j.is_number() || !std::isfinite(j.get<double>()) || j.get<double>() < lo ||
            j.get<double>() > hi)
            bad(key,
                "must be a number in [" + std::to_string(lo) + ", " + std::to_string(hi) + "]");
        return j.get<double>();
    }
    ScreenPoint point(const Json& j, const std::string& key) const
    {
        if (!j.is_array() || j.size() != 2)
            bad(key, "must be a point [x, y] in pixels");
        return {number(j[0], key, -1e6, 1e6), number(j[1], key, -1e6, 1e6), 0};
    }
};

const std::pair<const char*, StandardView> kViews[] = {
    {"front", StandardView::Front}, {"back", StandardView::Back}, {"right", StandardView::Right},
    {"left", StandardView::Left},   {"top", StandardView::Top},   {"bottom", StandardView::Bottom}};

ScriptAction parse_action(const Json& j, const Reader& r)
{
    ScriptAction a;
    a.where = r.where;
    if (!j.is_object())
        fail(r.name, r.where, "an action must be a JSON object");
    static const char* const kinds[] = {"tool",          "elements",  "through",
                                        "brush_radius",  "drag",      "click",
                                        "scroll",        "select",    "undo",
                                        "redo",          "view",      "projection",
                                        "screenshot",    "save_mesh", "create_set",
                                        "delete_set",    "show_set",  "hide_set",
                                        "select_set",    "move_pins", "normal_direction",
                                        "solver",        "step",      "play",
                                        "reset",         "apply",     "export_recipe",
                                        "import_recipe", "noise",     "heat_map",
                                        "autosave",      "recover"};
    // Options, and the one action each belongs to.
    static const std::pair<const char*, const char*> options[] = {{"name", "create_set"},
                                                                  {"offset", "move_pins"},
                                                                  {"direction", "normal_direction"},
                                                                  {"seed", "noise"}};
    std::string kind;
    for (const auto& item : j.items())
    {
        const std::string& key = item.key();
        if (key == "modifiers" || key == "button" || key == "at")
            continue;
        if (std::any_of(std::begin(options), std::end(options),
                        [&](const auto& o) { return key == o.first; }))
            continue;
        if (std::find(std::begin(kinds), std::end(kinds), key) == std::end(kinds))
            r.bad(key, "is not an action or an action's option");
        if (!kind.empty())
            fail(r.name, r.where, "has two actions ('" + kind + "' and '" + key + "')");
        kind = key;
    }
    if (kind.empty())
        fail(r.name, r.where, "names no action");
    const Json& v = j[kind];
    if (j.contains("modifiers"))
    {
        if (kind != "drag" && kind != "click")
            r.bad("modifiers", "only a drag or a click takes modifiers");
        if (!j["modifiers"].is_array())
            r.bad("modifiers", "must be a list of \"shift\", \"ctrl\", \"alt\"");
        for (const Json& m : j["modifiers"])
        {
            const std::string s = r.text(m, "modifiers");
            if (s == "shift")
                a.mods.shift = true;
            else if (s == "ctrl")
                a.mods.ctrl = true;
            else if (s == "alt")
                a.mods.alt = true;
            else
                r.bad("modifiers", "'" + s + "' is not shift, ctrl or alt");
        }
    }
    if (j.contains("button"))
    {
        if (kind != "drag")
            r.bad("button", "only a drag takes a button");
        const std::string b = r.text(j["button"], "button");
        if (b == "left")
            a.button = MouseButton::Left;
        else if (b == "middle")
            a.button = MouseButton::Middle;
        else if (b == "right")
            a.button = MouseButton::Right;
        else
            r.bad("button", "'" + b + "' is not left, middle or right");
    }
    if (j.contains("at") && kind != "scroll")
        r.bad("at", "only a scroll takes 'at'");
    for (const auto& [option, owner] : options)
        if (j.contains(option) && kind != owner)
            r.bad(option, std::string("only ") + owner + " takes '" + option + "'");
    const auto vector = [&](const char* key) {
        const Json& x = j[key];
        if (!x.is_array() || x.size() != 3)
            r.bad(key, "must be [x, y, z]");
        return Vec3{r.number(x[0], key, -1e9, 1e9), r.number(x[1], key, -1e9, 1e9),
                    r.number(x[2], key, -1e9, 1e9)};
    };
    const auto count = [&](int lo, int hi) {
        if (!v.is_number_integer() || v.get<long long>() < lo || v.get<long long>() > hi)
            r.bad(kind, "must be a count from " + std::to_string(lo) + " to " + std::to_string(hi));
        return static_cast<int>(v.get<long long>());
    };

    if (kind == "tool")
    {
        a.kind = Kind::Tool;
        a.text = r.text(v, kind);
        if (!tool_named(a.text))
            r.bad(kind, "'" + a.text + "' is not navigate, click, brush, rectangle or lasso");
    }
    else if (kind == "elements")
    {
        a.kind = Kind::Elements;
        a.text = r.text(v, kind);
        if (a.text != "vertices" && a.text != "faces")
            r.bad(kind, "must be \"vertices\" or \"faces\"");
    }
    else if (kind == "through")
    {
        a.kind = Kind::Through;
        if (!v.is_boolean())
            r.bad(kind, "must be true or false");
        a.value = v.get<bool>() ? 1 : 0;
    }
    else if (kind == "brush_radius")
    {
        a.kind = Kind::BrushRadius;
        a.value = r.number(v, kind, 1, 1000);
    }
    else if (kind == "drag")
    {
        a.kind = Kind::Drag;
        if (!v.is_array() || v.size() < 2)
            r.bad(kind, "must be a list of at least 2 points [x, y]");
        for (const Json& p : v)
            a.points.push_back(r.point(p, kind));
    }
    else if (kind == "click")
    {
        a.kind = Kind::Click;
        a.points.push_back(r.point(v, kind));
    }
    else if (kind == "scroll")
    {
        a.kind = Kind::Scroll;
        a.value = r.number(v, kind, -100, 100);
        if (!j.contains("at"))
            r.bad(kind, "needs 'at': the cursor [x, y]");
        a.points.push_back(r.point(j["at"], "at"));
    }
    else if (kind == "select")
    {
        a.kind = Kind::Select;
        a.text = r.text(v, kind);
        if (!selection_command_named(a.text))
            r.bad(kind, "'" + a.text +
                            "' is not all, clear, invert, grow, shrink, connected or boundary");
    }
    else if (kind == "undo" || kind == "redo")
    {
        a.kind = kind == "undo" ? Kind::Undo : Kind::Redo;
        if (!v.is_number_integer() || v.get<long long>() < 1 || v.get<long long>() > 100000)
            r.bad(kind, "must be a count from 1 to 100000");
        a.count = static_cast<int>(v.get<long long>());
    }
    else if (kind == "view")
    {
        a.kind = Kind::View;
        a.text = r.text(v, kind);
        bool known = a.text == "all" || a.text == "selection";
        for (const auto& [view_name, view] : kViews)
            known = known || a.text == view_name;
        if (!known)
            r.bad(kind, "'" + a.text +
                            "' is not front, back, right, left, top, bottom, all or selection");
    }
    else if (kind == "projection")
    {
        a.kind = Kind::Projection;
        a.text = r.text(v, kind);
        if (a.text != "perspective" && a.text != "orthographic")
            r.bad(kind, "must be \"perspective\" or \"orthographic\"");
    }
    else if (kind == "create_set")
    {
        a.kind = Kind::CreateSet;
        a.text = r.text(v, kind);
        if (!kind_named(a.text))
            r.bad(kind, "'" + a.text +
                            "' is not region, pin, anchor, centroid, normal, "
                            "hard_normal or soft_normal");
        if (j.contains("name"))
            a.name = r.text(j["name"], "name");
    }
    else if (kind == "delete_set" || kind == "show_set" || kind == "hide_set" ||
             kind == "select_set" || kind == "move_pins" || kind == "normal_direction")
    {
        a.kind = kind == "delete_set"         ? Kind::DeleteSet
                 : kind == "select_set"       ? Kind::SelectSet
                 : kind == "move_pins"        ? Kind::MovePins
                 : kind == "normal_direction" ? Kind::NormalDirection
                                              : Kind::ShowSet;
        a.value = kind == "hide_set" ? 0 : 1;
        a.name = r.text(v, kind);
        if (kind == "move_pins")
        {
            if (!j.contains("offset"))
                r.bad(kind, "needs 'offset': [x, y, z]");
            a.vector = vector("offset");
        }
        if (kind == "normal_direction")
        {
            if (!j.contains("direction"))
                r.bad(kind, "needs 'direction': [x, y, z]");
            a.vector = vector("direction");
            if (a.vector == Vec3{0, 0, 0})
                r.bad("direction", "must not be zero");
        }
    }
    else if (kind == "solver")
    {
        a.kind = Kind::Solver;
        if (!v.is_object())
            r.bad(kind, "must be an object of solver settings");
        SolverSettings& s = a.settings;
        for (const auto& [key, value] : v.items())
        {
            const std::string k = "solver." + key;
            a.keys.push_back(key);
            if (key == "lambda")
            {
                if (value.is_string() && value.get<std::string>() == "optimal")
                    s.optimal_step = true;
                else
                    s.lambda = r.number(value, k, 1e-9, 1e3);
            }
            else if (key == "iterations_per_frame")
                s.iterations_per_frame = static_cast<int>(r.number(value, k, 1, 100000));
            else if (key == "tolerance")
                s.tolerance = r.number(value, k, 0, 1);
            else if (key == "anchor_mu")
                s.anchor_mu = r.number(value, k, 0, 1e12);
            else if (key == "centroid_mu")
                s.centroid_mu = r.number(value, k, 0, 1e12);
            else if (key == "normal_mu")
                s.normal_mu = r.number(value, k, 0, 1e12);
            else if (key == "soft_normal_mu")
                s.soft_normal_mu = r.number(value, k, 0, 1e12);
            else if (key == "gamma")
                s.gamma = r.number(value, k, 0, 1e12);
            else if (key == "normal_smoothing_iterations")
                s.normal_smoothing_iterations = static_cast<int>(r.number(value, k, 0, 100000));
            else if (key == "normal_smoothing_lambda")
                s.normal_smoothing_lambda = r.number(value, k, 1e-9, 1e3);
            else if (key == "joint")
            {
                if (!value.is_boolean())
                    r.bad(k, "must be true or false");
                s.joint = value.get<bool>();
            }
            else if (key == "denominator")
            {
                const std::string d = r.text(value, k);
                if (d != "paper" && d != "exact")
                    r.bad(k, "must be \"paper\" or \"exact\"");
                s.denominator =
                    d == "exact" ? CentroidDenominator::Exact : CentroidDenominator::Paper;
            }
            else if (key == "normals")
            {
                const std::string n = r.text(value, k);
                if (n != "initial" && n != "smoothed")
                    r.bad(k, "must be \"initial\" or \"smoothed\"");
                s.normal_source = n == "smoothed" ? NormalSource::Smoothed : NormalSource::Initial;
            }
            else
                r.bad(k, "is not a solver setting");
        }
    }
    else if (kind == "step" || kind == "play")
    {
        a.kind = kind == "step" ? Kind::Step : Kind::Play;
        a.count = count(1, 1000000);
    }
    else if (kind == "heat_map")
    {
        a.kind = Kind::HeatMap;
        a.text = r.text(v, kind);
        if (a.text != "off" && !heat_term_named(a.text))
            r.bad(kind, "'" + a.text + "' is not off, total, edge, anchor, centroid or normal");
    }
    else if (kind == "noise")
    {
        a.kind = Kind::Noise;
        a.value = r.number(v, kind, 0, 10);
        a.count = 1;
        if (j.contains("seed"))
        {
            const Json& seed = j["seed"];
            if (!seed.is_number_integer() || seed.get<long long>() < 0 ||
                seed.get<long long>() > 2147483647)
                r.bad("seed", "must be an integer from 0 to 2147483647");
            a.count = static_cast<int>(seed.get<long long>());
        }
    }
    else if (kind == "reset" || kind == "apply" || kind == "autosave" || kind == "recover")
    {
        a.kind = kind == "reset"      ? Kind::Reset
                 : kind == "apply"    ? Kind::Apply
                 : kind == "autosave" ? Kind::Autosave
                                      : Kind::Recover;
        if (!v.is_boolean() || !v.get<bool>())
            r.bad(kind, "must be true");
    }
    else
    {
        a.kind = kind == "screenshot"      ? Kind::Screenshot
                 : kind == "save_mesh"     ? Kind::SaveMesh
                 : kind == "export_recipe" ? Kind::ExportRecipe
                                           : Kind::ImportRecipe;
        a.text = r.text(v, kind);
        if (a.text.empty())
            r.bad(kind, "must be a file name");
    }
    return a;
}

// The session's settings with the keys an action gives replaced.
SolverSettings merged_settings(const ScriptAction& a, SolverSettings s)
{
    const SolverSettings& g = a.settings;
    for (const std::string& key : a.keys)
    {
        if (key == "lambda")
        {
            s.optimal_step = g.optimal_step;
            s.lambda = g.optimal_step ? s.lambda : g.lambda;
        }
        else if (key == "iterations_per_frame")
            s.iterations_per_frame = g.iterations_per_frame;
        else if (key == "tolerance")
            s.tolerance = g.tolerance;
        else if (key == "anchor_mu")
            s.anchor_mu = g.anchor_mu;
        else if (key == "centroid_mu")
            s.centroid_mu = g.centroid_mu;
        else if (key == "normal_mu")
            s.normal_mu = g.normal_mu;
        else if (key == "soft_normal_mu")
            s.soft_normal_mu = g.soft_normal_mu;
        else if (key == "gamma")
            s.gamma = g.gamma;
        else if (key == "normal_smoothing_iterations")
            s.normal_smoothing_iterations = g.normal_smoothing_iterations;
        else if (key == "normal_smoothing_lambda")
            s.normal_smoothing_lambda = g.normal_smoothing_lambda;
        else if (key == "joint")
            s.joint = g.joint;
        else if (key == "denominator")
            s.denominator = g.denominator;
        else if (key == "normals")
            s.normal_source = g.normal_source;
    }
    return s;
}

// Live solving for `frames` frames of the solver's thread, as the window shows them.
void play_frames(EditorSession& session, int frames)
{
    session.play(frames); // the solver pauses by itself after them
    while (session.playing())
        session.take_frame();
}

} // namespace

Script parse_script(const std::string& text, const std::string& name)
{
    Json j;
    try
    {
        j = Json::parse(text);
    }
    catch (const Json::parse_error& e)
    {
        throw json_syntax_error(name, e.what());
    }
    catch (const Json::exception& e)
    {
        throw InvalidInputError("'" + name + "': not valid JSON: " + e.what());
    }
    const Json* list = &j;
    if (j.is_object())
    {
        for (const auto& [key, value] : j.items())
            if (key != "actions")
                fail(name, key, "is unknown (a script is {\"actions\": [...]})");
        if (!j.contains("actions"))
            fail(name, "actions", "is missing");
        list = &j["actions"];
    }
    if (!list->is_array())
        fail(name, "actions", "must be a list of actions");
    Script script;
    script.name = name;
    for (size_t k = 0; k < list->size(); ++k)
        script.actions.push_back(
            parse_action((*list)[k], Reader{name, "actions[" + std::to_string(k) + "]"}));
    return script;
}

Script read_script(const std::string& path)
{
    return parse_script(io::read_file(path), path);
}

void play_script(const Script& script, EditorSession& session, ScriptHost& host)
{
    const auto set_index = [&](const ScriptAction& a) {
        const std::optional<size_t> k = session.set_named(a.name);
        if (!k)
            fail(script.name, a.where, "no set named '" + a.name + "'");
        return *k;
    };
    // Framebuffer pixels to the view's, as the window's cursor() does.
    auto in_view = [&](const ScreenPoint& p) {
        const ViewRect& v = session.view_rect();
        return ScreenPoint{p.x - v.x, p.y - v.y, 0};
    };
    for (const ScriptAction& a : script.actions)
    {
        host.layout();
        UiRequests r;
        switch (a.kind)
        {
            case Kind::Tool:
                r.tool = tool_named(a.text);
                break;
            case Kind::Elements:
                r.elements = a.text == "faces" ? ElementKind::Faces : ElementKind::Vertices;
                break;
            case Kind::Through:
                session.tool_settings().through = a.value != 0;
                break;
            case Kind::BrushRadius:
                session.tool_settings().brush_radius_px = a.value;
                break;
            case Kind::Drag:
            {
                const ScreenPoint first = in_view(a.points.front());
                session.mouse_press(a.button, a.mods, first.x, first.y);
                for (size_t k = 1; k < a.points.size(); ++k)
                {
                    const ScreenPoint p = in_view(a.points[k]);
                    session.mouse_move(p.x, p.y);
                }
                const ScreenPoint last = in_view(a.points.back());
                session.mouse_release(a.button, last.x, last.y);
                break;
            }
            case Kind::Click:
            {
                const ScreenPoint p = in_view(a.points[0]);
                session.mouse_press(MouseButton::Left, a.mods, p.x, p.y);
                session.mouse_release(MouseButton::Left, p.x, p.y);
                break;
            }
            case Kind::Scroll:
            {
                const ScreenPoint p = in_view(a.points[0]);
                session.scroll(a.value, p.x, p.y);
                break;
            }
            case Kind::Select:
                r.command = selection_command_named(a.text);
                break;
            case Kind::Undo:
            case Kind::Redo:
                for (int k = 0; k < a.count; ++k)
                {
                    UiRequests step;
                    (a.kind == Kind::Undo ? step.undo : step.redo) = true;
                    session.carry_out(step);
                }
                break;
            case Kind::View:
                if (a.text == "all")
                    r.frame_all = true;
                else if (a.text == "selection")
                    r.frame_selection = true;
                else
                    for (const auto& [view_name, view] : kViews)
                        if (a.text == view_name)
                            r.view = view;
                break;
            case Kind::Projection:
                if ((a.text == "orthographic") !=
                    (session.camera().projection == Projection::Orthographic))
                    r.toggle_projection = true;
                break;
            case Kind::Screenshot:
                host.screenshot(a.text);
                break;
            case Kind::SaveMesh:
                if (!session.save(a.text))
                    throw WriteError(a.where + ": " + session.state().message);
                break;
            case Kind::CreateSet:
                if (!session.create_set(*kind_named(a.text), a.name))
                    fail(script.name, a.where, session.state().message);
                break;
            case Kind::DeleteSet:
                session.delete_set(set_index(a));
                break;
            case Kind::ShowSet:
                session.set_visible(set_index(a), a.value != 0);
                break;
            case Kind::SelectSet:
                session.select_set(set_index(a));
                break;
            case Kind::MovePins:
            {
                const size_t k = set_index(a);
                if (session.document().sets[k].kind != ConstraintKind::Pin)
                    fail(script.name, a.where, "set '" + a.name + "' is not a pin set");
                session.move_pins(k, a.vector);
                break;
            }
            case Kind::NormalDirection:
            {
                const size_t k = set_index(a);
                if (session.document().sets[k].faces.empty())
                    fail(script.name, a.where, "set '" + a.name + "' has no faces");
                session.set_normal_direction(k, a.vector);
                break;
            }
            case Kind::Solver:
                session.set_solver_settings(merged_settings(a, session.document().solver), false);
                break;
            case Kind::Step:
            case Kind::Play:
                if (!session.problems().empty())
                    fail(script.name, a.where, "cannot solve: " + session.problems().front());
                if (a.kind == Kind::Step)
                    session.step(a.count);
                else
                    play_frames(session, a.count);
                break;
            case Kind::Autosave:
                session.autosave(0);
                break;
            case Kind::Recover:
                if (!session.recover())
                    fail(script.name, a.where, session.state().message);
                break;
            case Kind::HeatMap:
                session.set_heat_map(heat_term_named(a.text));
                session.wait_for_heat();
                break;
            case Kind::Noise:
                session.add_noise(a.value, static_cast<std::uint64_t>(a.count));
                break;
            case Kind::Reset:
                session.reset_shape();
                break;
            case Kind::Apply:
                session.apply_shape();
                break;
            case Kind::ExportRecipe:
                if (!session.export_recipe(a.text))
                    throw WriteError(a.where + ": " + session.state().message);
                break;
            case Kind::ImportRecipe:
                if (!session.import_recipe(a.text))
                    fail(script.name, a.where, session.state().message);
                break;
        }
        session.carry_out(r);
        session.seal_history(); // each action is an undo step of its own
    }
}

} // namespace meshfair::app
