// SPDX-License-Identifier: MIT
// Copyright 2026 the MeshFair authors.
//
// The operator definitions of the commands (app/edit/command.h) and what is derived from
// them: the undo steps, the script reader and its dictionaries, the menus' shortcuts.
#include "app/edit/command.h"

#include <doctest/doctest.h>

#include <algorithm>
#include <set>
#include <variant>

#include "app/editor/key_map.h"
#include "app/editor/script.h"
#include "core/errors.h"
#include "core/io/io.h"
#include "tests/helpers.h"

using namespace meshfair;
using namespace meshfair::app;

namespace {

// Every command, default-constructed.
template <size_t... I>
std::vector<Command> every_command(std::index_sequence<I...>)
{
    return {Command(std::variant_alternative_t<I, Command>{})...};
}
std::vector<Command> every_command()
{
    return every_command(std::make_index_sequence<std::variant_size_v<Command>>{});
}

// The message a one-action script is refused with, or "" when it is read.
std::string refusal(const std::string& action)
{
    try
    {
        parse_script("[" + action + "]", "s.json");
    }
    catch (const InvalidInputError& e)
    {
        return e.what();
    }
    return "";
}

} // namespace

TEST_SUITE("Operators")
{
    TEST_CASE("every command's definition names it and says what its undo step keeps")
    {
        const std::vector<Command> commands = every_command();
        REQUIRE(commands.size() == std::variant_size_v<Command>);
        for (const Command& c : commands)
        {
            const CommandSpec spec = spec_of(c);
            CAPTURE(command_name(c));
            CHECK_FALSE(command_name(c).empty());
            CHECK_FALSE(menu_label(c).empty());
            // An undo step has a name in the Edit menu, and keeps some part; a command that
            // makes none keeps nothing.
            CHECK(spec.label.empty() == (spec.captures == 0));
            // What it changes and does not keep would be lost by undo, but for the positions
            // of a solver step, which the solver publishes itself.
            CHECK((spec.bumps & ~spec.captures & ~(kSetMembers | kSets | kSettings)) == 0);
        }
    }

    TEST_CASE("the undo steps whose names and parts depend on the command's values")
    {
        CHECK(spec_of(cmd::EnableSet{"a", true}).label == "enable set");
        CHECK(spec_of(cmd::EnableSet{"a", false}).label == "disable set");
        CHECK(spec_of(cmd::RunSelection{SelectionCommand::Grow}).label == "select grow");
        cmd::ApplySelection lasso;
        lasso.tool = ToolKind::Lasso;
        CHECK(spec_of(lasso).label == "lasso select");
        CHECK_FALSE(spec_of(lasso).waits_for_gesture);
        cmd::MovePins move{"pins", {1, 0, 0}};
        CHECK((spec_of(move).bumps & kSettings) == 0);
        move.dome = SolverSettings{};
        CHECK((spec_of(move).bumps & kSettings) != 0);
        cmd::PaintDab dab;
        CHECK(spec_of(dab).captures == (kSets | kPositions));
        CHECK(spec_of(dab).stops_run);
        dab.mode = PaintMode::Add;
        CHECK(spec_of(dab).captures == kSets);
        CHECK_FALSE(spec_of(dab).stops_run);
    }

    TEST_CASE("every script action is refused, named, when its value has the wrong type")
    {
        const std::vector<ScriptActionSyntax> actions = script_actions();
        REQUIRE(actions.size() > 35);
        std::set<std::string_view> names;
        for (const ScriptActionSyntax& a : actions)
        {
            CAPTURE(a.name);
            CHECK(names.insert(a.name).second); // one reader per action
            // No action takes a list of lists of objects.
            const std::string action = "{\"" + std::string(a.name) + "\": [[{}]]}";
            CHECK(refusal(action).find("'s.json': actions[0]." + std::string(a.name)) == 0);
            // An option beside an action that does not take it names the actions that do.
            for (const std::string_view option : a.options)
            {
                const std::string other = a.name == "frames" ? "move" : "frames";
                const std::string wrong =
                    "{\"" + other + "\": 1, \"" + std::string(option) + "\": 1}";
                const std::string message = refusal(wrong);
                CHECK(message.find("actions[0]." + std::string(option) + ": only ") !=
                      std::string::npos);
                CHECK(message.find(std::string(a.name)) != std::string::npos);
            }
        }
    }

    TEST_CASE("the script reader reads commands from their definitions' fields")
    {
        const Script s = parse_script(
            R"([{"create_set": "pin", "name": "top", "close_holes": false},
                {"rename_set": "top", "name": "lid"}, {"noise": 0.25, "seed": 7},
                {"normal_direction": "n", "direction": [0, 0, 2]}, {"solve": true},
                {"save_mesh": "out.obj"}, {"hide_set": "lid"}, {"up_axis": "-z"}])",
            "s.json");
        REQUIRE(s.actions.size() == 8);
        CHECK(s.actions[0].commands[0] ==
              Command(cmd::CreateSet{ConstraintKind::Pin, "top", false}));
        CHECK(s.actions[1].commands[0] == Command(cmd::RenameSet{"top", "lid"}));
        CHECK(s.actions[2].commands[0] == Command(cmd::AddNoise{0.25, 7}));
        CHECK(s.actions[3].commands[0] == Command(cmd::SetNormalDirection{"n", {0, 0, 2}}));
        CHECK(s.actions[4].commands[0] == Command(cmd::Solve{}));
        CHECK(s.actions[5].commands[0] == Command(cmd::SaveMesh{"out.obj"}));
        CHECK(s.actions[5].writes);
        CHECK(s.actions[6].commands[0] == Command(cmd::ShowSet{"lid", false}));
        CHECK(s.actions[7].commands[0] == Command(cmd::SetUpAxis{UpAxis::NegZ}));
        // Required options, values out of range, zero vectors and no-field actions.
        CHECK(refusal(R"({"rename_set": "a"})") ==
              "'s.json': actions[0].rename_set: needs 'name': the new name");
        CHECK(refusal(R"({"noise": 0.1, "seed": -1})") ==
              "'s.json': actions[0].seed: must be an integer in [0, 2147483647] (got -1)");
        CHECK(refusal(R"({"normal_direction": "n", "direction": [0, 0, 0]})") ==
              "'s.json': actions[0].direction: must not be zero");
        CHECK(refusal(R"({"solve": false})") == "'s.json': actions[0].solve: must be true");
        CHECK(refusal(R"({"save_mesh": ""})") ==
              "'s.json': actions[0].save_mesh: must be a file name");
        CHECK(refusal(R"({"elements": "edges"})") ==
              "'s.json': actions[0].elements: 'edges' is not vertices or faces");
    }

    TEST_CASE("the fuzzer's dictionary and docs/editor.md name every script action and option")
    {
        const std::string dict = io::read_file(
            (test::assets_dir() / ".." / "tests" / "fuzz" / "dict" / "script.dict").string());
        const std::string doc =
            io::read_file((test::assets_dir() / ".." / "docs" / "editor.md").string());
        for (const ScriptActionSyntax& a : script_actions())
        {
            CAPTURE(a.name);
            const std::string quoted = "\"" + std::string(a.name) + "\"";
            CHECK(dict.find("\"\\" + quoted.substr(0, quoted.size() - 1) + "\\\"\"") !=
                  std::string::npos);
            CHECK(doc.find("`{" + quoted + ":") != std::string::npos);
            for (const std::string_view option : a.options)
            {
                const std::string o = "\"" + std::string(option) + "\"";
                CAPTURE(option);
                CHECK(dict.find("\"\\" + o.substr(0, o.size() - 1) + "\\\"\"") !=
                      std::string::npos);
                CHECK(doc.find(o + ":") != std::string::npos);
            }
        }
    }

    TEST_CASE("a menu's shortcut is the key that gives its command")
    {
        size_t shown = 0;
        for (const Command& c : every_command())
        {
            const std::optional<KeyChord> chord = key_for(c);
            if (!chord)
                continue;
            ++shown;
            CAPTURE(menu_label(c));
            const std::optional<Command> given = command_for_key(*chord);
            REQUIRE(given.has_value());
            CHECK(*given == c);
        }
        CHECK(shown >= 10);
        CHECK(chord_label(*key_for(cmd::Redo{})) == "Ctrl+Shift+Z");
        CHECK(chord_label(*key_for(cmd::ToggleProjection{})) == "Numpad 5");
        CHECK(menu_label(cmd::SetUpAxis{UpAxis::NegZ}) == "Up axis -Z");
        CHECK(menu_label(cmd::ShowDialog{cmd::Dialog::ExportRecipe}) == "Export recipe...");
    }
}
