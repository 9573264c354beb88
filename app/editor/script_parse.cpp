// SPDX-License-Identifier: MIT
// Copyright 2026 the MeshFair authors.
#include "app/editor/script.h"

#include <algorithm>
#include <cmath>
#include <nlohmann/json.hpp>

#include "app/editor/heat_map.h"
#include "app/editor/key_map.h"
#include "core/errors.h"
#include "core/io/io.h"
#include "core/recipe/recipe_json.h"

namespace meshfair::app {

namespace {

using Json = nlohmann::json;
using Kind = ScriptAction::Kind;

struct Reader
{
    const std::string& name;
    std::string where;

    [[noreturn]] void bad(const std::string& key, const std::string& why) const
    {
        script_error(name, where + "." + key, why);
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
    int integer(const Json& j, const std::string& key, int lo, int hi) const
    {
        if (!j.is_number_integer() || j.get<long long>() < lo || j.get<long long>() > hi)
            bad(key, "must be a count from " + std::to_string(lo) + " to " + std::to_string(hi));
        return static_cast<int>(j.get<long long>());
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

// The session's settings with the keys an action gives replaced, kept apart: the action
// is parsed before any is played, its keys merged into the settings of the moment.
struct SolverChange
{
    SolverSettings settings;
    std::vector<std::string> keys;
};

// UTF-8 text as the characters a keyboard types.
std::vector<InputEvent> typed(const std::string& text)
{
    std::vector<InputEvent> events;
    for (size_t k = 0; k < text.size();)
    {
        const auto c = static_cast<unsigned char>(text[k]);
        const int length = c < 0x80 ? 1 : c < 0xE0 ? 2 : c < 0xF0 ? 3 : 4;
        unsigned code = length == 1 ? c : c & (0x3F >> (length - 1));
        for (int i = 1; i < length && k + static_cast<size_t>(i) < text.size(); ++i)
            code =
                (code << 6) | (static_cast<unsigned char>(text[k + static_cast<size_t>(i)]) & 0x3F);
        InputEvent e;
        e.type = InputEvent::Type::Char;
        e.key = static_cast<int>(code);
        events.push_back(e);
        k += static_cast<size_t>(length);
    }
    return events;
}

ScriptAction parse_action(const Json& j, const Reader& r)
{
    ScriptAction a;
    a.where = r.where;
    if (!j.is_object())
        script_error(r.name, r.where, "an action must be a JSON object");
    static const char* const kinds[] = {"tool",
                                        "elements",
                                        "through",
                                        "brush_radius",
                                        "drag",
                                        "click",
                                        "scroll",
                                        "move",
                                        "key",
                                        "type",
                                        "click_widget",
                                        "frames",
                                        "select",
                                        "undo",
                                        "redo",
                                        "view",
                                        "projection",
                                        "screenshot",
                                        "save_mesh",
                                        "create_set",
                                        "delete_set",
                                        "show_set",
                                        "hide_set",
                                        "select_set",
                                        "move_pins",
                                        "rename_set",
                                        "normal_direction",
                                        "solver",
                                        "step",
                                        "play",
                                        "reset",
                                        "apply",
                                        "export_recipe",
                                        "import_recipe",
                                        "noise",
                                        "heat_map",
                                        "autosave",
                                        "recover",
                                        "up_axis",
                                        "paint",
                                        "paint_settings",
                                        "preset",
                                        "solve",
                                        "cancel_preparation"};
    // Options, and the actions each belongs to.
    static const std::pair<const char*, const char*> options[] = {
        {"name", "create_set rename_set"},
        {"close_holes", "create_set"},
        {"offset", "move_pins"},
        {"direction", "normal_direction"},
        {"seed", "noise"},
        {"modifiers", "drag click click_widget"},
        {"button", "drag"},
        {"at", "scroll"}};
    std::string kind;
    for (const auto& item : j.items())
    {
        const std::string& key = item.key();
        if (std::any_of(std::begin(options), std::end(options),
                        [&](const auto& o) { return key == o.first; }))
            continue;
        if (std::find(std::begin(kinds), std::end(kinds), key) == std::end(kinds))
            r.bad(key, "is not an action or an action's option");
        if (!kind.empty())
            script_error(r.name, r.where, "has two actions ('" + kind + "' and '" + key + "')");
        kind = key;
    }
    if (kind.empty())
        script_error(r.name, r.where, "names no action");
    for (const auto& [option, owners] : options)
    {
        const std::string list = std::string(" ") + owners + " ";
        if (j.contains(option) && list.find(" " + kind + " ") == std::string::npos)
        {
            // "only drag or click takes 'button'"
            std::string who, word;
            for (size_t p = 0, q; p < std::string(owners).size(); p = q + 1)
            {
                q = std::string(owners).find(' ', p);
                word = std::string(owners).substr(p, q == std::string::npos ? q : q - p);
                who += (who.empty() ? "" : q == std::string::npos ? " or " : ", ") + word;
                if (q == std::string::npos)
                    break;
            }
            r.bad(option, "only " + who + " takes '" + option + "'");
        }
    }
    const Json& v = j[kind];
    if (j.contains("modifiers"))
    {
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
    MouseButton button = MouseButton::Left;
    if (j.contains("button"))
    {
        const std::string b = r.text(j["button"], "button");
        if (b == "left")
            button = MouseButton::Left;
        else if (b == "middle")
            button = MouseButton::Middle;
        else if (b == "right")
            button = MouseButton::Right;
        else
            r.bad("button", "'" + b + "' is not left, middle or right");
    }
    const auto vector = [&](const char* key) {
        const Json& x = j[key];
        if (!x.is_array() || x.size() != 3)
            r.bad(key, "must be [x, y, z]");
        return Vec3{r.number(x[0], key, -1e9, 1e9), r.number(x[1], key, -1e9, 1e9),
                    r.number(x[2], key, -1e9, 1e9)};
    };
    const auto count = [&](int lo, int hi) { return r.integer(v, kind, lo, hi); };
    const auto command = [&](Command c) { a.commands.push_back(std::move(c)); };
    using namespace cmd;

    if (kind == "tool")
    {
        const std::string t = r.text(v, kind);
        const std::optional<ToolKind> tool = tool_named(t);
        if (!tool)
            r.bad(kind, "'" + t +
                            "' is not navigate, click, brush, rectangle, lasso, move_pins, "
                            "aim_normals or paint");
        command(SetTool{*tool});
    }
    else if (kind == "elements")
    {
        const std::string e = r.text(v, kind);
        if (e != "vertices" && e != "faces")
            r.bad(kind, "must be \"vertices\" or \"faces\"");
        command(SetElements{e == "faces" ? ElementKind::Faces : ElementKind::Vertices});
    }
    else if (kind == "through")
    {
        if (!v.is_boolean())
            r.bad(kind, "must be true or false");
        command(SetThrough{v.get<bool>()});
    }
    else if (kind == "brush_radius")
        command(SetBrushRadius{r.number(v, kind, 1, 1000)});
    else if (kind == "drag")
    {
        a.kind = Kind::Input;
        if (!v.is_array() || v.size() < 2)
            r.bad(kind, "must be a list of at least 2 points [x, y]");
        std::vector<ScreenPoint> points;
        for (const Json& p : v)
            points.push_back(r.point(p, kind));
        a.events = drag_events(points, button, a.mods);
    }
    else if (kind == "click")
    {
        a.kind = Kind::Input;
        const ScreenPoint p = r.point(v, kind);
        a.events = drag_events({p, p}, MouseButton::Left, a.mods);
        a.events.erase(a.events.begin() + 2); // no move between the press and the release
    }
    else if (kind == "move")
    {
        a.kind = Kind::Input;
        a.events = {input_event(InputEvent::Type::MouseMove, r.point(v, kind))};
    }
    else if (kind == "scroll")
    {
        a.kind = Kind::Input;
        if (!j.contains("at"))
            r.bad(kind, "needs 'at': the cursor [x, y]");
        const ScreenPoint at = r.point(j["at"], "at");
        InputEvent wheel = input_event(InputEvent::Type::Scroll, at);
        wheel.amount = r.number(v, kind, -100, 100);
        a.events = {input_event(InputEvent::Type::MouseMove, at), wheel};
    }
    else if (kind == "key")
    {
        a.kind = Kind::Input;
        const std::string text = r.text(v, kind);
        const std::optional<KeyChord> chord = parse_key_chord(text);
        if (!chord)
            r.bad(kind, "'" + text + "' is not a key (\"ctrl+z\", \"space\", \"f1\", \"kp_5\")");
        a.events = key_events(*chord);
    }
    else if (kind == "type")
    {
        a.kind = Kind::Input;
        a.events = typed(r.text(v, kind));
    }
    else if (kind == "click_widget")
    {
        a.kind = Kind::ClickWidget;
        a.text = r.text(v, kind);
        if (a.text.empty())
            r.bad(kind, "must be a widget's label");
    }
    else if (kind == "frames")
    {
        a.kind = Kind::Frames;
        a.count = count(1, 10000);
    }
    else if (kind == "select")
    {
        const std::string c = r.text(v, kind);
        const std::optional<SelectionCommand> sc = selection_command_named(c);
        if (!sc)
            r.bad(kind,
                  "'" + c + "' is not all, clear, invert, grow, shrink, connected or boundary");
        command(RunSelection{*sc});
    }
    else if (kind == "undo" || kind == "redo")
    {
        a.repeat = count(1, 100000);
        command(kind == "undo" ? Command(Undo{}) : Command(Redo{}));
    }
    else if (kind == "view")
    {
        const std::string name = r.text(v, kind);
        if (name == "all")
            command(FrameAll{});
        else if (name == "selection")
            command(FrameSelection{});
        else
        {
            for (const auto& [view_name, view] : kViews)
                if (name == view_name)
                    command(SetView{view});
            if (a.commands.empty())
                r.bad(kind, "'" + name +
                                "' is not front, back, right, left, top, bottom, all or selection");
        }
    }
    else if (kind == "up_axis")
    {
        const std::optional<UpAxis> up = up_axis_named(r.text(v, kind));
        if (!up)
            r.bad(kind, "must be \"+x\", \"-x\", \"+y\", \"-y\", \"+z\" or \"-z\"");
        command(SetUpAxis{*up});
    }
    else if (kind == "projection")
    {
        const std::string p = r.text(v, kind);
        if (p != "perspective" && p != "orthographic")
            r.bad(kind, "must be \"perspective\" or \"orthographic\"");
        command(SetProjection{p == "orthographic" ? Projection::Orthographic
                                                  : Projection::Perspective});
    }
    else if (kind == "create_set")
    {
        const std::string k = r.text(v, kind);
        if (!kind_named(k))
            r.bad(kind, "'" + k +
                            "' is not region, pin, anchor, centroid, normal, hard_normal or "
                            "soft_normal");
        bool close_holes = true;
        if (j.contains("close_holes"))
        {
            if (!j["close_holes"].is_boolean())
                r.bad("close_holes", "must be true or false");
            close_holes = j["close_holes"].get<bool>();
        }
        command(CreateSet{*kind_named(k), j.contains("name") ? r.text(j["name"], "name") : "",
                          close_holes});
    }
    else if (kind == "delete_set")
        command(DeleteSet{r.text(v, kind)});
    else if (kind == "show_set" || kind == "hide_set")
        command(ShowSet{r.text(v, kind), kind == "show_set"});
    else if (kind == "select_set")
        command(SelectSet{r.text(v, kind)});
    else if (kind == "rename_set")
    {
        if (!j.contains("name"))
            r.bad(kind, "needs 'name': the new name");
        command(RenameSet{r.text(v, kind), r.text(j["name"], "name")});
    }
    else if (kind == "move_pins")
    {
        if (!j.contains("offset"))
            r.bad(kind, "needs 'offset': [x, y, z]");
        command(MovePins{r.text(v, kind), vector("offset")});
    }
    else if (kind == "normal_direction")
    {
        if (!j.contains("direction"))
            r.bad(kind, "needs 'direction': [x, y, z]");
        const Vec3 d = vector("direction");
        if (d == Vec3{0, 0, 0})
            r.bad("direction", "must not be zero");
        command(SetNormalDirection{r.text(v, kind), d});
    }
    else if (kind == "preset")
        command(ApplyPreset{r.text(v, kind)});
    else if (kind == "paint" || kind == "paint_settings")
    {
        // A stroke's dabs ("paint"), or the Paint tool's settings for strokes given as input.
        if (!v.is_object())
            r.bad(kind, "must be an object");
        const bool stroke = kind == "paint";
        std::vector<std::string> keys = {"set", "mode", "strength", "curve", "steps"};
        if (stroke)
            keys.insert(keys.end(), {"radius", "dabs"});
        for (const auto& item : v.items())
            if (std::find(keys.begin(), keys.end(), item.key()) == keys.end())
                r.bad(kind + "." + item.key(), "is not a key of '" + kind + "'");
        PaintSettings p;
        if (v.contains("set"))
            p.set = r.text(v["set"], kind + ".set");
        if (v.contains("mode"))
        {
            const std::optional<PaintMode> mode =
                paint_mode_named(r.text(v["mode"], kind + ".mode"));
            if (!mode)
                r.bad(kind + ".mode", "must be \"relax\", \"add\", \"subtract\" or \"smooth\"");
            p.mode = *mode;
        }
        if (v.contains("strength"))
            p.strength = r.number(v["strength"], kind + ".strength", 0, 1);
        if (v.contains("curve"))
        {
            const std::optional<FalloffCurve> curve =
                falloff_curve_named(r.text(v["curve"], kind + ".curve"));
            if (!curve)
                r.bad(kind + ".curve",
                      "must be \"smooth\", \"sphere\", \"root\", \"linear\", "
                      "\"sharp\" or \"constant\"");
            p.curve = *curve;
        }
        if (v.contains("steps"))
        {
            p.steps = r.integer(v["steps"], kind + ".steps", 1, 10000);
        }
        if (!stroke)
            command(SetPaintSettings{p});
        else
        {
            if (!v.contains("radius") || !v.contains("dabs") || !v["dabs"].is_array() ||
                v["dabs"].empty())
                r.bad(kind, "needs 'radius' and 'dabs': a list of centres [x, y, z]");
            const Scalar radius = r.number(v["radius"], kind + ".radius", 1e-12, 1e12);
            const std::string set = p.set.empty() ? std::string(kPaintSet) : p.set;
            for (size_t k = 0; k < v["dabs"].size(); ++k)
            {
                const Json& c = v["dabs"][k];
                const std::string key = kind + ".dabs[" + std::to_string(k) + "]";
                if (!c.is_array() || c.size() != 3)
                    r.bad(key, "must be [x, y, z]");
                command(
                    PaintDab{set,
                             p.mode,
                             {r.number(c[0], key, -1e12, 1e12), r.number(c[1], key, -1e12, 1e12),
                              r.number(c[2], key, -1e12, 1e12)},
                             radius,
                             p.strength,
                             p.curve,
                             p.steps});
            }
            a.interaction = "stroke"; // one undo step, as the tool's stroke
        }
    }
    else if (kind == "solver")
    {
        if (!v.is_object())
            r.bad(kind, "must be an object of solver settings");
        SolverChange change;
        SolverSettings& s = change.settings;
        for (const auto& [key, value] : v.items())
        {
            const std::string k = "solver." + key;
            change.keys.push_back(key);
            if (key == "lambda")
            {
                if (value.is_string() && value.get<std::string>() == "optimal")
                    s.optimal_step = true;
                else
                    s.lambda = r.number(value, k, 1e-9, 1e3);
            }
            else if (key == "iterations_per_frame")
                s.iterations_per_frame = r.integer(value, k, 1, 100000);
            else if (key == "steps_per_run")
                s.steps_per_run = r.integer(value, k, 1, 100000);
            else if (key == "until_converged")
            {
                if (!value.is_boolean())
                    r.bad(k, "must be true or false");
                s.until_converged = value.get<bool>();
            }
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
                s.normal_smoothing_iterations = r.integer(value, k, 0, 100000);
            else if (key == "strength")
            {
                s.adaptive_smoothing = AdaptiveIterations{};
                s.adaptive_smoothing->strength = r.number(value, k, 0, 10);
            }
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
            else if (key == "method")
            {
                const std::string m = r.text(value, k);
                if (m != "jacobi" && m != "taubin" && m != "direct" && m != "cg" && m != "implicit")
                    r.bad(k,
                          "must be \"jacobi\", \"taubin\", \"direct\", \"cg\" or "
                          "\"implicit\"");
                s.method = m == "taubin"     ? Method::Taubin
                           : m == "direct"   ? Method::Direct
                           : m == "cg"       ? Method::ConjugateGradient
                           : m == "implicit" ? Method::Implicit
                                             : Method::Jacobi;
            }
            else if (key == "time")
                s.time = r.number(value, k, 1e-6, 1e6);
            else if (key == "taubin_mu")
                s.taubin_mu = r.number(value, k, -1e3, 0);
            else if (key == "keep_volume" || key == "prevent_flips")
            {
                if (!value.is_boolean())
                    r.bad(k, "must be true or false");
                (key == "keep_volume" ? s.keep_volume : s.prevent_flips) = value.get<bool>();
            }
            else if (key == "bilateral" || key == "falloff" || key == "bending")
            {
                // A recipe's object (docs/recipe.md), or null for none.
                if (!value.is_null())
                    try
                    {
                        if (key == "bilateral")
                            s.bilateral = parse_bilateral(value, k);
                        else if (key == "bending")
                            s.bending = parse_bending(value, k);
                        else
                            s.falloff = parse_falloff(value, k);
                    }
                    catch (const RecipeError& e)
                    {
                        r.bad(e.key(), e.message());
                    }
            }
            else
                r.bad(k, "is not a solver setting");
        }
        // The settings of the moment with these keys: merged when the action is played.
        a.keys = change.keys;
        command(SetSolverSettings{change.settings});
    }
    else if (kind == "step")
        command(Step{count(1, 1000000)});
    else if (kind == "play")
    {
        a.kind = Kind::Play;
        a.count = count(1, 1000000);
    }
    else if (kind == "heat_map")
    {
        const std::string t = r.text(v, kind);
        if (t != "off" && !heat_term_named(t))
            r.bad(kind, "'" + t + "' is not off, total, edge, anchor, centroid or normal");
        command(SetHeatMap{heat_term_named(t)});
        a.waits_for_heat = true;
    }
    else if (kind == "noise")
    {
        std::uint64_t seed = 1;
        if (j.contains("seed"))
        {
            const Json& s = j["seed"];
            if (!s.is_number_integer() || s.get<long long>() < 0 || s.get<long long>() > 2147483647)
                r.bad("seed", "must be an integer from 0 to 2147483647");
            seed = static_cast<std::uint64_t>(s.get<long long>());
        }
        command(AddNoise{r.number(v, kind, 0, 10), seed});
    }
    else if (kind == "reset" || kind == "apply" || kind == "autosave" || kind == "recover" ||
             kind == "solve" || kind == "cancel_preparation")
    {
        if (!v.is_boolean() || !v.get<bool>())
            r.bad(kind, "must be true");
        command(kind == "reset"                ? Command(ResetShape{})
                : kind == "apply"              ? Command(ApplyShape{})
                : kind == "autosave"           ? Command(Autosave{})
                : kind == "solve"              ? Command(Solve{})
                : kind == "cancel_preparation" ? Command(CancelPreparation{})
                                               : Command(Recover{}));
    }
    else
    {
        const std::string path = r.text(v, kind);
        if (path.empty())
            r.bad(kind, "must be a file name");
        if (kind == "screenshot")
        {
            a.kind = Kind::Screenshot;
            a.text = path;
        }
        else if (kind == "save_mesh")
            command(SaveMesh{path});
        else if (kind == "export_recipe")
            command(ExportRecipe{path});
        else
            command(ImportRecipe{path});
        a.writes = kind != "import_recipe";
    }
    return a;
}

} // namespace

void script_error(const std::string& name, const std::string& where, const std::string& why)
{
    throw InvalidInputError("'" + name + "': " + where + ": " + why);
}

InputEvent input_event(InputEvent::Type type, ScreenPoint p, MouseButton button, Modifiers mods)
{
    InputEvent e;
    e.type = type;
    e.x = p.x;
    e.y = p.y;
    e.button = button;
    e.mods = mods;
    return e;
}

std::vector<InputEvent> key_events(const KeyChord& chord)
{
    std::vector<InputEvent> events;
    const auto key_event = [&](InputEvent::Type type, int code, Modifiers mods) {
        InputEvent e;
        e.type = type;
        e.key = code;
        e.mods = mods;
        events.push_back(e);
    };
    // The modifiers go down one after the other, each event carrying those held before it.
    Modifiers held;
    if (chord.mods.ctrl)
    {
        key_event(InputEvent::Type::KeyPress, key::LeftControl, held);
        held.ctrl = true;
    }
    if (chord.mods.shift)
    {
        key_event(InputEvent::Type::KeyPress, key::LeftShift, held);
        held.shift = true;
    }
    if (chord.mods.alt)
    {
        key_event(InputEvent::Type::KeyPress, key::LeftAlt, held);
        held.alt = true;
    }
    key_event(InputEvent::Type::KeyPress, chord.key, held);
    // A printable key without Ctrl or Alt also types its character.
    if (!held.ctrl && !held.alt && chord.key >= key::Space && chord.key < key::Escape)
    {
        InputEvent c;
        c.type = InputEvent::Type::Char;
        c.key =
            chord.key >= 'A' && chord.key <= 'Z' && !held.shift ? chord.key - 'A' + 'a' : chord.key;
        events.push_back(c);
    }
    key_event(InputEvent::Type::KeyRelease, chord.key, held);
    if (held.alt)
        key_event(InputEvent::Type::KeyRelease, key::LeftAlt, held);
    held.alt = false;
    if (held.shift)
        key_event(InputEvent::Type::KeyRelease, key::LeftShift, held);
    held.shift = false;
    if (held.ctrl)
        key_event(InputEvent::Type::KeyRelease, key::LeftControl, held);
    return events;
}

// A drag as a mouse gives it: move there, press, move through the points, release.
std::vector<InputEvent> drag_events(const std::vector<ScreenPoint>& points, MouseButton button,
                                    Modifiers mods)
{
    std::vector<InputEvent> events{
        input_event(InputEvent::Type::MouseMove, points.front()),
        input_event(InputEvent::Type::MousePress, points.front(), button, mods)};
    for (size_t k = 1; k < points.size(); ++k)
        events.push_back(input_event(InputEvent::Type::MouseMove, points[k]));
    events.push_back(input_event(InputEvent::Type::MouseRelease, points.back(), button, mods));
    return events;
}

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
                script_error(name, key, "is unknown (a script is {\"actions\": [...]})");
        if (!j.contains("actions"))
            script_error(name, "actions", "is missing");
        list = &j["actions"];
    }
    if (!list->is_array())
        script_error(name, "actions", "must be a list of actions");
    Script script;
    script.name = name;
    for (size_t k = 0; k < list->size(); ++k)
        script.actions.push_back(
            parse_action((*list)[k], Reader{name, "actions[" + std::to_string(k) + "]"}));
    return script;
}

std::string stroke_action(std::span<const cmd::PaintDab> dabs)
{
    if (dabs.empty())
        return {};
    const cmd::PaintDab& first = dabs.front();
    Json centres = Json::array();
    for (const cmd::PaintDab& d : dabs)
        centres.push_back({d.center[0], d.center[1], d.center[2]});
    const Json action = {{"paint",
                          {{"set", first.set},
                           {"mode", std::string(paint_mode_name(first.mode))},
                           {"radius", first.radius},
                           {"strength", first.strength},
                           {"curve", std::string(falloff_curve_name(first.curve))},
                           {"steps", first.steps},
                           {"dabs", centres}}}};
    return action.dump();
}

Script read_script(const std::string& path)
{
    return parse_script(io::read_file(path), path);
}

} // namespace meshfair::app
