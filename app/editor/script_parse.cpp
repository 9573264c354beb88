// SPDX-License-Identifier: MIT
// Copyright 2026 the MeshFair authors.
#include "app/editor/script.h"

#include <algorithm>
#include <cmath>
#include <nlohmann/json.hpp>
#include <tuple>
#include <type_traits>
#include <utility>
#include <variant>

#include "app/editor/heat_map.h"
#include "app/editor/key_map.h"
#include "core/errors.h"
#include "core/io/checked_json.h"
#include "core/io/io.h"
#include "core/recipe/recipe_json.h"

namespace meshfair::app {

namespace {

using Kind = ScriptAction::Kind;

// A point of the view [x, y] in pixels.
ScreenPoint point(const CheckedJson& j)
{
    if (!j.is_array() || j.size() != 2)
        j.fail("must be a point [x, y] in pixels");
    return {j.at(0).number(-1e6, 1e6), j.at(1).number(-1e6, 1e6), 0};
}

// A count in [lo, hi].
int count(const CheckedJson& j, int lo, int hi)
{
    return static_cast<int>(j.integer(lo, hi));
}

const std::pair<const char*, StandardView> kViews[] = {
    {"front", StandardView::Front}, {"back", StandardView::Back}, {"right", StandardView::Right},
    {"left", StandardView::Left},   {"top", StandardView::Top},   {"bottom", StandardView::Bottom}};

constexpr std::pair<std::string_view, PaintMode> kPaintModes[] = {{"relax", PaintMode::Relax},
                                                                  {"add", PaintMode::Add},
                                                                  {"subtract", PaintMode::Subtract},
                                                                  {"smooth", PaintMode::Smooth}};
constexpr std::pair<std::string_view, CentroidDenominator> kDenominators[] = {
    {"paper", CentroidDenominator::Paper}, {"exact", CentroidDenominator::Exact}};
constexpr std::pair<std::string_view, NormalSource> kNormalSources[] = {
    {"initial", NormalSource::Initial}, {"smoothed", NormalSource::Smoothed}};
constexpr std::pair<std::string_view, Method> kMethods[] = {{"jacobi", Method::Jacobi},
                                                            {"taubin", Method::Taubin},
                                                            {"direct", Method::Direct},
                                                            {"cg", Method::ConjugateGradient},
                                                            {"implicit", Method::Implicit}};

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

// What an action's reader is given: the action's object, its action key and value.
struct ActionArgs
{
    const CheckedJson& j; //!< the action's object
    const std::string& kind;
    const CheckedJson& v; //!< its value
};

// One script action: its key, the options it takes beside it, and its reader.
struct ActionForm
{
    std::string_view name;
    std::vector<std::string_view> options;
    void (*read)(const ActionArgs&, ScriptAction&);
};

// --- Commands read from their definitions' fields (app/edit/operator.h).

template <class C, class T>
void read_field(const ActionArgs& x, const Field<C, T>& f, C& c)
{
    const bool own_value = f.place == FieldPlace::Value;
    const std::string key = own_value ? x.kind : std::string(f.key);
    if (!own_value && !x.j.has(key))
    {
        if (f.place == FieldPlace::RequiredOption)
            x.v.fail("needs '" + key + "': " + std::string(f.doc));
        return;
    }
    const CheckedJson v = own_value ? x.v : x.j[key];
    T& out = c.*(f.member);
    if constexpr (std::is_same_v<T, std::string>)
    {
        out = v.text();
        if (!f.doc.empty() && out.empty())
            v.fail("must be " + std::string(f.doc));
    }
    else if constexpr (std::is_same_v<T, bool>)
        out = v.boolean();
    else if constexpr (std::is_enum_v<T>)
    {
        const std::string name = v.text();
        const std::optional<T> named = f.named(name);
        if (!named)
            v.fail("'" + name + "' is not " + std::string(f.choices));
        out = *named;
    }
    else if constexpr (std::is_same_v<T, Vec3>)
    {
        const std::array<double, 3> p = v.vec3();
        out = {p[0], p[1], p[2]};
        if (f.nonzero && out == Vec3{0, 0, 0})
            v.fail("must not be zero");
    }
    else if constexpr (std::is_integral_v<T>)
        out = static_cast<T>(v.integer(static_cast<long long>(f.lo), static_cast<long long>(f.hi)));
    else
    {
        static_assert(std::is_floating_point_v<T>, "a field's type the script reader knows");
        out = v.number(f.lo, f.hi);
    }
}

template <class C>
void read_fields(const ActionArgs& x, ScriptAction& a)
{
    C c{};
    // A command with no fields is given by `"action": true`.
    if constexpr (std::tuple_size_v<std::decay_t<decltype(C::fields)>> == 0)
    {
        if (!x.v.is_bool() || !x.v.boolean())
            x.v.fail("must be true");
    }
    std::apply([&](const auto&... f) { (read_field(x, f, c), ...); }, C::fields);
    a.commands.push_back(std::move(c));
}

// --- Commands whose definitions give them a reader of their own (own_reader).

void read_action(std::type_identity<cmd::Undo>, const ActionArgs& x, ScriptAction& a)
{
    a.repeat = count(x.v, 1, 100000);
    a.commands.push_back(cmd::Undo{});
}

void read_action(std::type_identity<cmd::Redo>, const ActionArgs& x, ScriptAction& a)
{
    a.repeat = count(x.v, 1, 100000);
    a.commands.push_back(cmd::Redo{});
}

// A standard view, or the whole mesh or the selection framed.
void read_action(std::type_identity<cmd::SetView>, const ActionArgs& x, ScriptAction& a)
{
    const std::string name = x.v.text();
    if (name == "all")
        a.commands.push_back(cmd::FrameAll{});
    else if (name == "selection")
        a.commands.push_back(cmd::FrameSelection{});
    for (const auto& [view_name, view] : kViews)
        if (name == view_name)
            a.commands.push_back(cmd::SetView{view});
    if (a.commands.empty())
        x.v.fail("'" + name + "' is not front, back, right, left, top, bottom, all or selection");
}

// "show_set" or "hide_set".
void read_action(std::type_identity<cmd::ShowSet>, const ActionArgs& x, ScriptAction& a)
{
    a.commands.push_back(cmd::ShowSet{x.v.text(), x.kind == cmd::ShowSet::info.script});
}

void read_action(std::type_identity<cmd::Play>, const ActionArgs& x, ScriptAction& a)
{
    a.kind = Kind::Play;
    a.count = count(x.v, 1, 1000000);
}

void read_action(std::type_identity<cmd::SetHeatMap>, const ActionArgs& x, ScriptAction& a)
{
    const std::string t = x.v.text();
    if (t != "off" && !heat_term_named(t))
        x.v.fail("'" + t + "' is not off, total, edge, anchor, centroid or normal");
    a.commands.push_back(cmd::SetHeatMap{heat_term_named(t)});
    a.waits_for_heat = true;
}

// The Paint tool's settings for strokes given as input ("paint_settings"), or a stroke's
// dabs ("paint"), which share the settings' keys.
void read_paint(const ActionArgs& x, ScriptAction& a, bool stroke)
{
    const std::string& kind = x.kind;
    const CheckedJson& v = x.v;
    if (!v.is_object())
        v.fail("must be an object");
    std::vector<std::string> keys = {"set", "mode", "strength", "curve", "steps"};
    if (stroke)
        keys.insert(keys.end(), {"radius", "dabs"});
    for (const auto& [key, value] : v.members())
        if (std::find(keys.begin(), keys.end(), key) == keys.end())
            value.fail("is not a key of '" + kind + "'");
    PaintSettings p;
    if (v.has("set"))
        p.set = v["set"].text();
    if (v.has("mode"))
        p.mode = v["mode"].choice(kPaintModes);
    if (v.has("strength"))
        p.strength = v["strength"].number(0, 1);
    if (v.has("curve"))
    {
        const std::optional<FalloffCurve> curve = falloff_curve_named(v["curve"].text());
        if (!curve)
            v["curve"].fail(
                "must be \"smooth\", \"sphere\", \"root\", \"linear\", "
                "\"sharp\" or \"constant\"");
        p.curve = *curve;
    }
    if (v.has("steps"))
        p.steps = count(v["steps"], 1, 10000);
    if (!stroke)
    {
        a.commands.push_back(cmd::SetPaintSettings{p});
        return;
    }
    if (!v.has("radius") || !v.has("dabs") || !v["dabs"].is_array() || v["dabs"].size() == 0)
        v.fail("needs 'radius' and 'dabs': a list of centres [x, y, z]");
    const Scalar radius = v["radius"].number(1e-12, 1e12);
    const std::string set = p.set.empty() ? std::string(kPaintSet) : p.set;
    // The dabs' centres read in one pass (a stroke has thousands).
    const CheckedJson dabs = v["dabs"];
    for (size_t k = 0; k < dabs.size(); ++k)
    {
        const CheckedJson c = dabs.at(k);
        if (!c.is_array() || c.size() != 3)
            c.fail("must be [x, y, z]");
        const std::vector<double> at = c.numbers(-1e12, 1e12);
        a.commands.push_back(cmd::PaintDab{
            set, p.mode, {at[0], at[1], at[2]}, radius, p.strength, p.curve, p.steps});
    }
    a.interaction = "stroke"; // one undo step, as the tool's stroke
}

void read_action(std::type_identity<cmd::PaintDab>, const ActionArgs& x, ScriptAction& a)
{
    read_paint(x, a, true);
}

void read_action(std::type_identity<cmd::SetPaintSettings>, const ActionArgs& x, ScriptAction& a)
{
    read_paint(x, a, false);
}

// The solver settings an action gives: only its keys, merged into the settings of the
// moment when the action is played (the action is read before any is played).
void read_action(std::type_identity<cmd::SetSolverSettings>, const ActionArgs& x, ScriptAction& a)
{
    if (!x.v.is_object())
        x.v.fail("must be an object of solver settings");
    SolverChange change;
    SolverSettings& s = change.settings;
    for (const auto& [key, value] : x.v.members())
    {
        change.keys.push_back(key);
        if (key == "lambda")
        {
            if (value.is_string() && value.text() == "optimal")
                s.optimal_step = true;
            else
                s.lambda = value.number(1e-9, 1e3);
        }
        else if (key == "iterations_per_frame")
            s.iterations_per_frame = count(value, 1, 100000);
        else if (key == "steps_per_run")
            s.steps_per_run = count(value, 1, 100000);
        else if (key == "until_converged")
            s.until_converged = value.boolean();
        else if (key == "tolerance")
            s.tolerance = value.number(0, 1);
        else if (key == "anchor_mu")
            s.anchor_mu = value.number(0, 1e12);
        else if (key == "centroid_mu")
            s.centroid_mu = value.number(0, 1e12);
        else if (key == "normal_mu")
            s.normal_mu = value.number(0, 1e12);
        else if (key == "soft_normal_mu")
            s.soft_normal_mu = value.number(0, 1e12);
        else if (key == "gamma")
            s.gamma = value.number(0, 1e12);
        else if (key == "normal_smoothing_iterations")
            s.normal_smoothing_iterations = count(value, 0, 100000);
        else if (key == "strength")
        {
            s.adaptive_smoothing = AdaptiveIterations{};
            s.adaptive_smoothing->strength = value.number(0, 10);
        }
        else if (key == "normal_smoothing_lambda")
            s.normal_smoothing_lambda = value.number(1e-9, 1e3);
        else if (key == "joint")
            s.joint = value.boolean();
        else if (key == "denominator")
            s.denominator = value.choice(kDenominators);
        else if (key == "normals")
            s.normal_source = value.choice(kNormalSources);
        else if (key == "method")
            s.method = value.choice(kMethods);
        else if (key == "time")
            s.time = value.number(1e-6, 1e6);
        else if (key == "taubin_mu")
            s.taubin_mu = value.number(-1e3, 0);
        else if (key == "keep_volume")
            s.keep_volume = value.boolean();
        else if (key == "prevent_flips")
            s.prevent_flips = value.boolean();
        // A recipe's object (docs/recipe.md), or null for none.
        else if (key == "bilateral")
            s.bilateral = value.is_null() ? std::nullopt : std::optional(parse_bilateral(value));
        else if (key == "bending")
            s.bending = value.is_null() ? std::nullopt : std::optional(parse_bending(value));
        else if (key == "falloff")
            s.falloff = value.is_null() ? std::nullopt : std::optional(parse_falloff(value));
        else
            value.fail("is not a solver setting");
    }
    // The settings of the moment with these keys: merged when the action is played.
    a.keys = change.keys;
    a.commands.push_back(cmd::SetSolverSettings{change.settings});
}

// --- Raw input, as a person gives it (no command of its own).

MouseButton read_button(const ActionArgs& x)
{
    if (!x.j.has("button"))
        return MouseButton::Left;
    static constexpr std::pair<std::string_view, MouseButton> kButtons[] = {
        {"left", MouseButton::Left},
        {"middle", MouseButton::Middle},
        {"right", MouseButton::Right}};
    return x.j["button"].choice(kButtons);
}

Modifiers read_modifiers(const ActionArgs& x)
{
    Modifiers mods;
    if (!x.j.has("modifiers"))
        return mods;
    const CheckedJson list = x.j["modifiers"];
    if (!list.is_array())
        list.fail("must be a list of \"shift\", \"ctrl\", \"alt\"");
    for (const CheckedJson& m : list.elements())
    {
        const std::string s = m.text();
        if (s == "shift")
            mods.shift = true;
        else if (s == "ctrl")
            mods.ctrl = true;
        else if (s == "alt")
            mods.alt = true;
        else
            list.fail("'" + s + "' is not shift, ctrl or alt");
    }
    return mods;
}

const ActionForm kInputForms[] = {
    {"drag",
     {"button", "modifiers"},
     [](const ActionArgs& x, ScriptAction& a) {
         a.kind = Kind::Input;
         a.mods = read_modifiers(x);
         if (!x.v.is_array() || x.v.size() < 2)
             x.v.fail("must be a list of at least 2 points [x, y]");
         std::vector<ScreenPoint> points;
         for (const CheckedJson& p : x.v.elements())
             points.push_back(point(p));
         a.events = drag_events(points, read_button(x), a.mods);
     }},
    {"click",
     {"modifiers"},
     [](const ActionArgs& x, ScriptAction& a) {
         a.kind = Kind::Input;
         a.mods = read_modifiers(x);
         const ScreenPoint p = point(x.v);
         a.events = drag_events({p, p}, MouseButton::Left, a.mods);
         a.events.erase(a.events.begin() + 2); // no move between the press and the release
     }},
    {"move",
     {},
     [](const ActionArgs& x, ScriptAction& a) {
         a.kind = Kind::Input;
         a.events = {input_event(InputEvent::Type::MouseMove, point(x.v))};
     }},
    {"scroll",
     {"at"},
     [](const ActionArgs& x, ScriptAction& a) {
         a.kind = Kind::Input;
         if (!x.j.has("at"))
             x.v.fail("needs 'at': the cursor [x, y]");
         const ScreenPoint at = point(x.j["at"]);
         InputEvent wheel = input_event(InputEvent::Type::Scroll, at);
         wheel.amount = x.v.number(-100, 100);
         a.events = {input_event(InputEvent::Type::MouseMove, at), wheel};
     }},
    {"key",
     {},
     [](const ActionArgs& x, ScriptAction& a) {
         a.kind = Kind::Input;
         const std::string text = x.v.text();
         const std::optional<KeyChord> chord = parse_key_chord(text);
         if (!chord)
             x.v.fail("'" + text + "' is not a key (\"ctrl+z\", \"space\", \"f1\", \"kp_5\")");
         a.events = key_events(*chord);
     }},
    {"type",
     {},
     [](const ActionArgs& x, ScriptAction& a) {
         a.kind = Kind::Input;
         a.events = typed(x.v.text());
     }},
    {"click_widget",
     {"modifiers"},
     [](const ActionArgs& x, ScriptAction& a) {
         a.kind = Kind::ClickWidget;
         a.mods = read_modifiers(x);
         a.text = x.v.text();
         if (a.text.empty())
             x.v.fail("must be a widget's label");
     }},
    {"frames",
     {},
     [](const ActionArgs& x, ScriptAction& a) {
         a.kind = Kind::Frames;
         a.count = count(x.v, 1, 10000);
     }},
    // The frame drawn so far, as the window shows it (not the Screenshot command, whose
    // frame is the next one drawn).
    {"screenshot",
     {},
     [](const ActionArgs& x, ScriptAction& a) {
         a.kind = Kind::Screenshot;
         a.text = x.v.text();
         if (a.text.empty())
             x.v.fail("must be a file name");
         a.writes = true;
     }},
};

// The form of command C's script action(s), from its definition: its fields' options,
// and its fields or its own reader.
template <class C>
void add_command_forms(std::vector<ActionForm>& forms)
{
    if constexpr (!C::info.script.empty())
    {
        ActionForm form{C::info.script, {}, nullptr};
        if constexpr (C::info.own_reader)
            form.read = [](const ActionArgs& x, ScriptAction& a) {
                read_action(std::type_identity<C>{}, x, a);
                a.writes = C::info.writes;
            };
        else
        {
            static_assert(HasFields<C>, "a command a script gives has fields or its own reader");
            std::apply(
                [&](const auto&... f) {
                    ((f.place != FieldPlace::Value ? form.options.push_back(f.key) : void()), ...);
                },
                C::fields);
            form.read = [](const ActionArgs& x, ScriptAction& a) {
                read_fields<C>(x, a);
                a.writes = C::info.writes;
            };
        }
        forms.push_back(form);
        if constexpr (!C::info.script_alias.empty())
        {
            form.name = C::info.script_alias;
            forms.push_back(form);
        }
    }
}

template <size_t... I>
void add_all_command_forms(std::vector<ActionForm>& forms, std::index_sequence<I...>)
{
    (add_command_forms<std::variant_alternative_t<I, Command>>(forms), ...);
}

// Every script action: the commands' (in the order of Command), then raw input.
const std::vector<ActionForm>& action_forms()
{
    static const std::vector<ActionForm> forms = [] {
        std::vector<ActionForm> all;
        add_all_command_forms(all, std::make_index_sequence<std::variant_size_v<Command>>{});
        all.insert(all.end(), std::begin(kInputForms), std::end(kInputForms));
        return all;
    }();
    return forms;
}

ScriptAction parse_action(const CheckedJson& j)
{
    ScriptAction a;
    a.where = j.path();
    if (!j.is_object())
        j.fail("an action must be a JSON object");
    const std::vector<ActionForm>& forms = action_forms();
    const auto is_option = [&](std::string_view key) {
        return std::any_of(forms.begin(), forms.end(), [&](const ActionForm& f) {
            return std::find(f.options.begin(), f.options.end(), key) != f.options.end();
        });
    };
    const std::vector<std::pair<std::string, CheckedJson>> members = j.members();
    const ActionForm* form = nullptr;
    for (const auto& [key, value] : members)
    {
        if (is_option(key))
            continue;
        const std::string& name = key; // (a lambda may not capture a structured binding)
        const auto named = std::find_if(forms.begin(), forms.end(),
                                        [&](const ActionForm& f) { return f.name == name; });
        if (named == forms.end())
            value.fail("is not an action or an action's option");
        if (form)
            j.fail("has two actions ('" + std::string(form->name) + "' and '" + key + "')");
        form = &*named;
    }
    if (!form)
        j.fail("names no action");
    // An option beside an action that does not take it: "only drag or click takes 'button'".
    for (const auto& [key, value] : members)
    {
        if (key == form->name ||
            std::find(form->options.begin(), form->options.end(), key) != form->options.end())
            continue;
        std::vector<std::string_view> owners;
        for (const ActionForm& f : forms)
            if (std::find(f.options.begin(), f.options.end(), key) != f.options.end())
                owners.push_back(f.name);
        std::string who;
        for (size_t k = 0; k < owners.size(); ++k)
            who += (k == 0 ? "" : k + 1 == owners.size() ? " or " : ", ") + std::string(owners[k]);
        value.fail("only " + who + " takes '" + key + "'");
    }
    const std::string kind(form->name);
    form->read(ActionArgs{j, kind, j[kind]}, a);
    return a;
}

} // namespace

std::vector<ScriptActionSyntax> script_actions()
{
    std::vector<ScriptActionSyntax> all;
    for (const ActionForm& f : action_forms())
        all.push_back({f.name, f.options});
    return all;
}

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
    const CheckedJson root = CheckedJson::parse(text, name);
    // {"actions": [...]} or the list by itself, its actions named "actions[k]" either way.
    const nlohmann::json* list = &root.raw();
    if (root.is_object())
    {
        root.only_keys({"actions"});
        list = &root["actions"].raw();
    }
    const CheckedJson actions(*list, name, "actions");
    if (!actions.is_array())
        actions.fail("must be a list of actions");
    Script script;
    script.name = name;
    for (const CheckedJson& action : actions.elements())
        script.actions.push_back(parse_action(action));
    return script;
}

std::string stroke_action(std::span<const cmd::PaintDab> dabs)
{
    if (dabs.empty())
        return {};
    const cmd::PaintDab& first = dabs.front();
    nlohmann::json centres = nlohmann::json::array();
    for (const cmd::PaintDab& d : dabs)
        centres.push_back({d.center[0], d.center[1], d.center[2]});
    const nlohmann::json action = {{"paint",
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
