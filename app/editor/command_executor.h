// SPDX-License-Identifier: MIT
// Copyright 2026 the MeshFair authors.
#pragma once

#include <string>

#include "app/editor/editor_session.h"
#include "core/errors.h"

namespace meshfair::app {

//! \brief Carries out each command on the session, once EditorSession::dispatch has done the
//! undo bookkeeping: true when it did something, false (with the message) when not. The
//! set-editing commands are in command_sets.cpp, painting in command_paint.cpp, the others in
//! command_dispatch.cpp.
struct CommandExecutor
{
    EditorSession& s;
    Document& d = s.document_;
    EditorState& st = s.state_;

    void say(std::string message) const
    {
        st.message = std::move(message);
        st.message_is_error = false;
    }
    bool fail(std::string message) const
    {
        st.message = std::move(message);
        st.message_is_error = true;
        return false;
    }
    size_t set_index(const std::string& name) const
    {
        const std::optional<size_t> k = s.set_named(name);
        if (!k)
            throw InvalidInputError("no set named '" + name + "'");
        return *k;
    }
    // --- Selection and tools.
    bool operator()(const cmd::SetTool& c) const;
    bool operator()(const cmd::SetElements& c) const;
    bool operator()(const cmd::ToggleElements&) const;
    bool operator()(const cmd::SetThrough& c) const;
    bool operator()(const cmd::SetBrushRadius& c) const;
    bool operator()(const cmd::ScaleBrushRadius& c) const;
    bool operator()(const cmd::RunSelection& c) const;
    bool operator()(const cmd::ApplySelection& c) const;
    // --- History.
    bool travel(bool back) const;
    bool operator()(const cmd::Undo&) const { return travel(true); }
    bool operator()(const cmd::Redo&) const { return travel(false); }

    // --- The view.
    bool operator()(const cmd::FrameAll&) const;
    bool operator()(const cmd::FrameSelection&) const;
    bool operator()(const cmd::SetView& c) const;
    bool operator()(const cmd::SetProjection& c) const;
    bool operator()(const cmd::ToggleProjection&) const;
    bool operator()(const cmd::SetOrbit& c) const;
    bool operator()(const cmd::ToggleOrbit&) const;
    bool operator()(const cmd::SetUpAxis& c) const;
    bool operator()(const cmd::Toggle& c) const;
    bool operator()(const cmd::SetDisplay& c) const;
    // --- Constraint sets.
    //! The selection as a set of `kind` takes it: vertex kinds take the selected vertices
    //! (or the vertices of the selected faces), face kinds the selected faces (or the faces
    //! whose vertices are all selected); a region keeps faces as faces.
    void selected_elements(ConstraintKind kind, std::vector<Index>& vertices,
                           std::vector<Index>& faces) const;
    bool operator()(const cmd::CreateSet& c) const;
    bool operator()(const cmd::DeleteSet& c) const;
    bool operator()(const cmd::RenameSet& c) const;
    bool operator()(const cmd::ShowSet& c) const;
    bool operator()(const cmd::SetColor& c) const;
    bool operator()(const cmd::SelectSet& c) const;
    bool operator()(const cmd::AddToSet& c) const;
    bool operator()(const cmd::RemoveFromSet& c) const;
    bool operator()(const cmd::CloseHoles& c) const;
    bool operator()(const cmd::EnableSet& c) const;
    bool operator()(const cmd::SetSetWeight& c) const;
    bool operator()(const cmd::SetNormalDirection& c) const;
    bool operator()(const cmd::MovePins& c) const;
    // --- Painting (command_paint.cpp).
    bool operator()(const cmd::PaintDab& c) const;
    bool operator()(const cmd::SetPaintSettings& c) const;
    // --- Solving.
    bool operator()(const cmd::SetSolverSettings& c) const;
    bool operator()(const cmd::Play& c) const;
    bool operator()(const cmd::Pause&) const;
    bool operator()(const cmd::TogglePlay&) const;
    bool operator()(const cmd::Step& c) const;
    bool operator()(const cmd::Solve& c) const;
    bool operator()(const cmd::CancelPreparation& c) const;
    bool operator()(const cmd::ResetShape&) const;
    bool operator()(const cmd::ApplyShape&) const;
    bool operator()(const cmd::AddNoise& c) const;
    bool operator()(const cmd::SetHeatMap& c) const;
    // --- Files and the program.
    bool operator()(const cmd::OpenMesh& c) const;
    bool operator()(const cmd::SaveMesh& c) const;
    bool operator()(const cmd::ExportRecipe& c) const;
    bool operator()(const cmd::ImportRecipe& c) const;
    bool operator()(const cmd::ApplyPreset& c) const;
    bool operator()(const cmd::ShowDialog& c) const;
    bool operator()(const cmd::Screenshot& c) const;
    bool operator()(const cmd::Quit&) const;
    bool operator()(const cmd::QuitDiscarding&) const;
    bool operator()(const cmd::Recover&) const;
    bool operator()(const cmd::DiscardRecovery&) const;
    bool operator()(const cmd::Autosave&) const;
};

} // namespace meshfair::app
