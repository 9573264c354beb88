// SPDX-License-Identifier: MIT
// Copyright 2026 the MeshFair authors.
// Script reader (docs/editor.md, "Scripted sessions"). The input is the script's JSON text,
// unchanged. An accepted script must hold what playing it relies on: each action named by
// its place; raw input with finite coordinates, every mouse button and key pressed in an
// action released in it after the press; typed text as the characters of its UTF-8; counts
// within the documented ranges; and a painted stroke, written back by stroke_action (what
// the editor's trace prints), read again as the same dabs bit for bit.

#include <cmath>
#include <cstddef>
#include <cstdint>
#include <cstdio>
#include <cstring>
#include <map>
#include <nlohmann/json.hpp>
#include <string>
#include <vector>

#include "app/editor/script.h"
#include "core/errors.h"
#include "tests/fuzz/fuzz_support.h"

namespace meshfair::fuzz {
namespace {

using app::InputEvent;
using app::Script;
using app::ScriptAction;
using Kind = ScriptAction::Kind;

bool same_bits(double a, double b)
{
    return std::memcmp(&a, &b, sizeof a) == 0;
}

bool same_dab(const app::cmd::PaintDab& a, const app::cmd::PaintDab& b)
{
    return a.set == b.set && a.mode == b.mode && same_bits(a.center[0], b.center[0]) &&
           same_bits(a.center[1], b.center[1]) && same_bits(a.center[2], b.center[2]) &&
           same_bits(a.radius, b.radius) && same_bits(a.strength, b.strength) &&
           a.curve == b.curve && a.steps == b.steps;
}

// The UTF-8 of one code point.
std::string utf8(unsigned code)
{
    std::string s;
    if (code < 0x80)
        s += static_cast<char>(code);
    else if (code < 0x800)
    {
        s += static_cast<char>(0xC0 | (code >> 6));
        s += static_cast<char>(0x80 | (code & 0x3F));
    }
    else if (code < 0x10000)
    {
        s += static_cast<char>(0xE0 | (code >> 12));
        s += static_cast<char>(0x80 | ((code >> 6) & 0x3F));
        s += static_cast<char>(0x80 | (code & 0x3F));
    }
    else
    {
        s += static_cast<char>(0xF0 | (code >> 18));
        s += static_cast<char>(0x80 | ((code >> 12) & 0x3F));
        s += static_cast<char>(0x80 | ((code >> 6) & 0x3F));
        s += static_cast<char>(0x80 | (code & 0x3F));
    }
    return s;
}

// Every press of a button or key in `events` released later in them, none released unpressed.
void check_input(const ScriptAction& a)
{
    std::map<std::pair<int, int>, int> held; // (0 button | 1 key, which) -> presses
    for (const InputEvent& e : a.events)
    {
        if (!std::isfinite(e.x) || !std::isfinite(e.y) || !std::isfinite(e.amount))
            fail(a.where + ": an input event with a coordinate that is not finite");
        const auto which = [&]() -> std::pair<int, int> {
            if (e.type == InputEvent::Type::MousePress || e.type == InputEvent::Type::MouseRelease)
                return {0, static_cast<int>(e.button)};
            return {1, e.key};
        };
        switch (e.type)
        {
            case InputEvent::Type::MousePress:
            case InputEvent::Type::KeyPress:
                ++held[which()];
                break;
            case InputEvent::Type::MouseRelease:
            case InputEvent::Type::KeyRelease:
                if (--held[which()] < 0)
                    fail(a.where + ": a button or key released that was not pressed");
                break;
            default:
                break;
        }
    }
    for (const auto& [what, presses] : held)
        if (presses != 0)
            fail(a.where + ": a button or key left pressed at the end of the action");
}

void check_stroke(const ScriptAction& a)
{
    std::vector<app::cmd::PaintDab> dabs;
    for (const app::Command& c : a.commands)
    {
        const auto* dab = std::get_if<app::cmd::PaintDab>(&c);
        if (dab == nullptr)
            fail(a.where + ": a stroke holds a command that is not a dab");
        dabs.push_back(*dab);
    }
    const std::string written = app::stroke_action(dabs);
    Script again;
    try
    {
        again = app::parse_script("[" + written + "]", "stroke.json");
    }
    catch (const InvalidInputError& e)
    {
        fail(a.where + ": stroke_action writes what parse_script refuses: " + e.what() + "\n" +
             written);
    }
    if (again.actions.size() != 1 || again.actions[0].commands.size() != dabs.size())
        fail(a.where + ": stroke_action's action has other dabs: " + written);
    for (size_t k = 0; k < dabs.size(); ++k)
    {
        const auto* dab = std::get_if<app::cmd::PaintDab>(&again.actions[0].commands[k]);
        if (dab == nullptr || !same_dab(*dab, dabs[k]))
            fail(a.where + ": dab " + std::to_string(k) + " differs once written: " + written);
    }
}

int test_one_input(const std::uint8_t* data, size_t size)
{
    if (size > kMaxInput)
        return 0;
    const std::string text(as_text(data, size));
    Script script;
    try
    {
        script = app::parse_script(text, "fuzz.json");
    }
    catch (const InvalidInputError& e)
    {
        if (verbose())
            std::fprintf(stderr, "refused: %s\n", e.what());
        return 0;
    }
    if (verbose())
        std::fprintf(stderr, "accepted: %zu actions\n", script.actions.size());
    if (script.name != "fuzz.json")
        fail("the script is not named by its file");
    // The same text as JSON: the actions' own values, to compare with what was read.
    const nlohmann::json j = nlohmann::json::parse(text);
    const nlohmann::json& list = j.is_object() ? j["actions"] : j;
    if (list.size() != script.actions.size())
        fail("the script has " + std::to_string(script.actions.size()) + " actions, its list " +
             std::to_string(list.size()));
    for (size_t k = 0; k < script.actions.size(); ++k)
    {
        const ScriptAction& a = script.actions[k];
        if (a.where != "actions[" + std::to_string(k) + "]")
            fail("action " + std::to_string(k) + " is named '" + a.where + "'");
        switch (a.kind)
        {
            case Kind::Commands:
                if (a.commands.empty() || a.repeat < 1 || a.repeat > 100000)
                    fail(a.where + ": no commands, or a repeat out of [1, 100000]");
                if (a.interaction == "stroke")
                    check_stroke(a);
                break;
            case Kind::Input:
                check_input(a);
                if (list[k].contains("type"))
                {
                    std::string typed;
                    for (const InputEvent& e : a.events)
                    {
                        if (e.type != InputEvent::Type::Char || e.key < 0 || e.key > 0x10FFFF)
                            fail(a.where + ": typed text gives an event that is not a character");
                        typed += utf8(static_cast<unsigned>(e.key));
                    }
                    if (typed != list[k]["type"].get<std::string>())
                        fail(a.where + ": the characters typed are not the text's");
                }
                else if (a.events.empty())
                    fail(a.where + ": raw input without events");
                break;
            case Kind::ClickWidget:
            case Kind::Screenshot:
                if (a.text.empty())
                    fail(a.where + ": a widget or file without a name");
                break;
            case Kind::Play:
            case Kind::Frames:
                if (a.count < 1 || a.count > 1000000)
                    fail(a.where + ": a count out of [1, 1000000]");
                break;
        }
    }
    return 0;
}

} // namespace
} // namespace meshfair::fuzz

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, size_t size)
{
    return meshfair::fuzz::test_one_input(data, size);
}
