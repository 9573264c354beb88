// SPDX-License-Identifier: MIT
// Copyright 2026 the MeshFair authors.
#include "app/editor/script.h"

#include <cmath>
#include <nlohmann/json.hpp>

#include "core/errors.h"
#include "core/io/io.h"

namespace meshfair::app {

namespace {

using Json = nlohmann::json;
using Kind = ScriptAction::Kind;

[[noreturn]] void fail(const std::string& name, const std::string& where, const std::string& why)
{
    throw InvalidInputError("'" + name + "': " + where + ": " + why);
}

// What JSON's parser says, as "'name':L:C: why".
[[noreturn]] void parse_failure(const std::string& name, const std::string& what)
{
    const auto at = what.find(" at line ");
    const auto why = what.find(": ", at == std::string::npos ? 0 : at);
    if (at == std::string::npos || why == std::string::npos)
        throw InvalidInputError("'" + name + "': not valid JSON: " + what);
    std::string place = what.substr(at + 9, why - at - 9); // "L, column C"
    const auto comma = place.find(", column ");
    if (comma != std::string::npos)
        place = place.substr(0, comma) + ":" + place.substr(comma + 9);
    throw InvalidInputError("'" + name + "':" + place +
                            ": not valid JSON: " + what.substr(why + 2));
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
    static const char* const kinds[] = {"tool",  "elements",   "through",    "brush_radius", "drag",
                                        "click", "scroll",     "select",     "undo",         "redo",
                                        "view",  "projection", "screenshot", "save_mesh"};
    std::string kind;
    for (const auto& [key, value] : j.items())
    {
        if (key == "modifiers" || key == "button" || key == "at")
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
    else
    {
        a.kind = kind == "screenshot" ? Kind::Screenshot : Kind::SaveMesh;
        a.text = r.text(v, kind);
        if (a.text.empty())
            r.bad(kind, "must be a file name");
    }
    return a;
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
        parse_failure(name, e.what());
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
        }
        session.carry_out(r);
    }
}

} // namespace meshfair::app
