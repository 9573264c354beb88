// SPDX-License-Identifier: MIT
// Copyright 2026 the MeshFair authors.
// Playing a script: its commands dispatched, its raw input through the input router.
#include "app/editor/script.h"

#include <iostream>

#include "app/editor/editor_frame.h"
#include "core/errors.h"

namespace meshfair::app {

namespace {

using Kind = ScriptAction::Kind;

// The session's settings with the keys an action gives replaced.
SolverSettings merged_settings(const SolverSettings& g, const std::vector<std::string>& keys,
                               SolverSettings s)
{
    for (const std::string& key : keys)
    {
        if (key == "lambda")
        {
            s.optimal_step = g.optimal_step;
            s.lambda = g.optimal_step ? s.lambda : g.lambda;
        }
        else if (key == "iterations_per_frame")
            s.iterations_per_frame = g.iterations_per_frame;
        else if (key == "steps_per_run")
            s.steps_per_run = g.steps_per_run;
        else if (key == "until_converged")
            s.until_converged = g.until_converged;
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
        {
            // A count replaces the iterations from the noise.
            s.normal_smoothing_iterations = g.normal_smoothing_iterations;
            s.adaptive_smoothing.reset();
        }
        else if (key == "strength")
        {
            // The strength turns the iterations from the noise on, as the panel's slider.
            s.adaptive_smoothing = s.adaptive_smoothing.value_or(AdaptiveIterations{});
            s.adaptive_smoothing->strength = g.adaptive_smoothing->strength;
        }
        else if (key == "normal_smoothing_lambda")
            s.normal_smoothing_lambda = g.normal_smoothing_lambda;
        else if (key == "joint")
            s.joint = g.joint;
        else if (key == "denominator")
            s.denominator = g.denominator;
        else if (key == "normals")
            s.normal_source = g.normal_source;
        else if (key == "method")
            s.method = g.method;
        else if (key == "taubin_mu")
            s.taubin_mu = g.taubin_mu;
        else if (key == "keep_volume")
            s.keep_volume = g.keep_volume;
        else if (key == "prevent_flips")
            s.prevent_flips = g.prevent_flips;
        else if (key == "bilateral")
            s.bilateral = g.bilateral;
        else if (key == "falloff")
            s.falloff = g.falloff;
        else if (key == "bending")
            s.bending = g.bending;
    }
    return s;
}

// The frames it takes for queued input to reach the session (one batch a frame).
void run_until_taken(EditorFrame& frame, ScriptHost& host)
{
    while (frame.input().pending())
        host.run_frame();
    host.run_frame();
}

} // namespace

void play_script(const Script& script, EditorSession& session, ScriptHost& host)
{
    EditorFrame& frame = host.frame_driver();
    host.run_frame(); // the interface laid out: widgets and the view's rectangle known
    for (const ScriptAction& a : script.actions)
    {
        switch (a.kind)
        {
            case Kind::Commands:
                for (int round = 0; round < a.repeat; ++round)
                    for (const Command& c : a.commands)
                    {
                        Command command = c;
                        if (auto* s = std::get_if<cmd::SetSolverSettings>(&command))
                        {
                            s->settings =
                                merged_settings(s->settings, a.keys, session.document().solver);
                        }
                        if (!session.dispatch(command, Interaction{a.interaction}) &&
                            session.state().message_is_error)
                        {
                            if (a.writes)
                                throw WriteError(a.where + ": " + session.state().message);
                            script_error(script.name, a.where, session.state().message);
                        }
                        // What a save wrote, and what its format could not hold, as the status
                        // line tells a person.
                        if (a.writes)
                            std::cerr << "meshfair: " << a.where << ": " << session.state().message
                                      << "\n";
                    }
                if (!a.interaction.empty())
                    session.end_interaction();
                if (a.waits_for_heat)
                    session.wait_for_heat();
                host.run_frame();
                break;
            case Kind::Input:
                for (const InputEvent& e : a.events)
                    frame.input().push(e);
                run_until_taken(frame, host);
                break;
            case Kind::ClickWidget:
            {
                // The panel as it is once the solver has prepared the last change: its
                // lines change then (the reason "until converged" is greyed goes, or comes),
                // moving what is below them; a person clicks what they see after it.
                session.settle_preparation();
                host.run_frame();
                // A widget scrolled out of the side panel is scrolled to with the wheel over
                // the panel, down then up, as a person does.
                const ViewRect& v = session.view_rect();
                const ScreenPoint panel{v.framebuffer_width - 170.0, v.framebuffer_height / 2.0, 0};
                for (int attempt = 0;
                     attempt < 40 && frame.has_interface() && !frame.ui().widget(a.text); ++attempt)
                {
                    InputEvent wheel = input_event(InputEvent::Type::Scroll, panel);
                    wheel.amount = attempt < 20 ? -3 : 3;
                    frame.input().push(input_event(InputEvent::Type::MouseMove, panel));
                    frame.input().push(wheel);
                    run_until_taken(frame, host);
                }
                const std::optional<WidgetRect> w = frame.ui().widget(a.text);
                if (!w)
                {
                    std::string names;
                    for (const std::string& n : frame.ui().widget_names())
                        names += (names.empty() ? "" : ", ") + n;
                    script_error(
                        script.name, a.where,
                        "no widget '" + a.text + "' on screen (" +
                            (frame.has_interface() ? "shown: " + names
                                                   : std::string("no interface: run with --ui")) +
                            ")");
                }
                const ScreenPoint p{w->center_x(), w->center_y(), 0};
                for (const InputEvent& e : drag_events({p, p}, MouseButton::Left, a.mods))
                    frame.input().push(e);
                run_until_taken(frame, host);
                break;
            }
            case Kind::Screenshot:
                host.screenshot(a.text);
                break;
            case Kind::Play:
                if (!session.dispatch(cmd::Play{a.count}))
                    script_error(script.name, a.where, session.state().message);
                while (session.playing())
                    session.take_frame();
                host.run_frame();
                // A run the recipe did not fit ends at once: the script stops with the
                // reason, as the status line gives it to a person.
                if (!session.state().solver.error.empty())
                    script_error(script.name, a.where,
                                 "cannot solve: " + session.state().solver.error);
                break;
            case Kind::Frames:
                for (int k = 0; k < a.count; ++k)
                    host.run_frame();
                break;
        }
        // The direct method solves by itself after the sets change (a command, a key, a
        // pin dragged): what comes next sees the minimizer, as a person does a moment later.
        if (solves_for_minimizer(session.document().solver.method) && a.kind != Kind::Screenshot)
        {
            session.settle_solver();
            host.run_frame();
        }
        session.end_interaction(); // each action is an undo step of its own
    }
}

} // namespace meshfair::app
