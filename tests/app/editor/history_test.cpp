// SPDX-License-Identifier: MIT
// Copyright 2026 the MeshFair authors.
// Undo and redo: any sequence of editor actions undone to the start returns the exact
// initial state, redo replays it bit for bit, and the history stays within its memory
// limit.
#include "app/editor/history.h"

#include <doctest/doctest.h>

#include <algorithm>
#include <random>

#include "app/editor/editor_session.h"
#include "app/render/recording_renderer.h"
#include "tests/helpers.h"

using namespace meshfair;
using namespace meshfair::app;

namespace {

constexpr int kHistoryWidth = 320, kHistoryHeight = 240;

struct Selection
{
    SelectionMask vertices, faces;
    bool operator==(const Selection&) const = default;
};

Selection selection_of(const Document& d)
{
    return {d.selected_vertices, d.selected_faces};
}

// One random action through the session's input calls, as the mouse and keys make them.
void random_action(EditorSession& s, std::mt19937& rng)
{
    std::uniform_real_distribution<double> x(-20, kHistoryWidth + 20), y(-20, kHistoryHeight + 20);
    std::uniform_int_distribution<int> pick(0, 99);
    const int what = pick(rng);
    const Modifiers mods{.shift = pick(rng) < 30, .ctrl = pick(rng) < 20, .alt = false};
    if (what < 10)
    {
        s.dispatch(cmd::RunSelection{static_cast<SelectionCommand>(pick(rng) % 7)});
        return;
    }
    if (what < 15)
    {
        s.dispatch(cmd::SetElements{pick(rng) % 2 ? ElementKind::Faces : ElementKind::Vertices});
        return;
    }
    if (what < 20)
    {
        s.dispatch(cmd::SetThrough{!s.tool_settings().through});
        return;
    }
    if (what < 25)
    {
        // An orbit in between: the next gestures see another view.
        s.dispatch(cmd::SetTool{ToolKind::Navigate});
        s.mouse_press(MouseButton::Left, {}, x(rng), y(rng));
        s.mouse_move(x(rng), y(rng));
        s.mouse_release(MouseButton::Left, 0, 0);
        return;
    }
    const ToolKind tools[] = {ToolKind::Click, ToolKind::Brush, ToolKind::Rectangle,
                              ToolKind::Lasso};
    s.dispatch(cmd::SetTool{tools[pick(rng) % 4]});
    s.dispatch(cmd::SetBrushRadius{double(4 + pick(rng) % 40)});
    s.mouse_press(MouseButton::Left, mods, x(rng), y(rng));
    for (int k = pick(rng) % 8; k > 0; --k)
        s.mouse_move(x(rng), y(rng));
    s.mouse_release(MouseButton::Left, x(rng), y(rng));
}

} // namespace

TEST_SUITE("History")
{
    TEST_CASE("any action sequence undone returns the initial state, redo replays it exactly")
    {
        for (const unsigned seed : {1u, 2u, 3u, 4u})
        {
            CAPTURE(seed);
            RecordingRenderer renderer;
            Mesh bunny_like = test::icosphere(3);
            EditorSession s(make_document(std::move(bunny_like), "sphere.obj"), renderer);
            s.state().offscreen = true;
            s.set_view_rect(ViewRect::whole(kHistoryWidth, kHistoryHeight));
            s.camera().frame(s.document().box, s.aspect());
            std::mt19937 rng(seed);

            // A non-empty start, so that "back to the start" is not "back to nothing".
            s.dispatch(cmd::SetTool{ToolKind::Rectangle});
            s.mouse_press(MouseButton::Left, {}, 100, 80);
            s.mouse_release(MouseButton::Left, 200, 160);
            s.history().clear();
            const Selection initial = selection_of(s.document());
            REQUIRE(std::count(initial.vertices.begin(), initial.vertices.end(), 1) > 0);

            // After each recorded step, the state it left.
            std::vector<Selection> states{initial};
            for (int k = 0; k < 60; ++k)
            {
                const std::size_t before = s.history().undo_count();
                random_action(s, rng);
                if (s.history().undo_count() > before)
                    states.push_back(selection_of(s.document()));
                else // an action that changed nothing records nothing
                    CHECK(selection_of(s.document()) == states.back());
            }
            REQUIRE(states.size() > 20);
            REQUIRE(s.history().undo_count() == states.size() - 1);
            for (size_t k = states.size() - 1; k > 0; --k)
            {
                REQUIRE(s.dispatch(cmd::Undo{}));
                CHECK(selection_of(s.document()) == states[k - 1]);
            }
            CHECK_FALSE(s.dispatch(cmd::Undo{}));
            CHECK(selection_of(s.document()) == initial);
            for (size_t k = 1; k < states.size(); ++k)
            {
                REQUIRE(s.dispatch(cmd::Redo{}));
                CHECK(selection_of(s.document()) == states[k]);
            }
            CHECK_FALSE(s.dispatch(cmd::Redo{}));
            // A new step after some undos drops what could have been redone.
            s.dispatch(cmd::Undo{});
            s.dispatch(cmd::Undo{});
            s.dispatch(cmd::RunSelection{SelectionCommand::Invert});
            CHECK(s.history().redo_count() == 0);
        }
    }

    TEST_CASE("the history keeps within its byte limit by dropping the oldest steps")
    {
        Document d = make_document(test::open_grid(30, 30), "grid.obj");
        const std::size_t mask = d.selected_vertices.size(); // one step's bytes
        History h(5 * mask);
        std::vector<SelectionMask> states{d.selected_vertices};
        for (int k = 0; k < 12; ++k)
        {
            EditState before = capture(d, kSelection);
            before.selected_faces.reset(); // as a vertex tool would leave it
            d.selected_vertices[static_cast<size_t>(k)] = 1;
            REQUIRE(h.record("step", std::move(before), d));
            states.push_back(d.selected_vertices);
            CHECK(h.bytes() <= h.limit());
        }
        CHECK(h.undo_count() == 5);
        CHECK(h.dropped() == 7);
        for (int k = 0; k < 5; ++k)
            REQUIRE(h.undo(d) != 0);
        CHECK(h.undo(d) == 0);
        CHECK(d.selected_vertices == states[12 - 5]); // as far back as was kept
        // A step that changed nothing is not recorded; the limit can be lowered later.
        CHECK_FALSE(h.record("nothing", capture(d, kSelection), d));
        h.set_limit(2 * mask);
        CHECK(h.bytes() <= 2 * mask);
        // The newest step is kept even when it alone is over the limit.
        History tiny(1);
        EditState before = capture(d, kSelection);
        d.selected_faces[0] = 1;
        CHECK(tiny.record("big", std::move(before), d));
        CHECK(tiny.undo_count() == 1);
        CHECK(tiny.bytes() == d.selected_faces.size());
    }
}
