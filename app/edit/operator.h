// SPDX-License-Identifier: MIT
// Copyright 2026 the MeshFair authors.
#pragma once

#include <cstdint>
#include <optional>
#include <string>
#include <string_view>
#include <tuple>
#include <type_traits>

#include "core/mesh/mesh.h"

//! \file
//! \brief The parts of an operator definition. Every command of the editor
//! (app/edit/command.h) defines itself in one place, as Blender's operators do: a static
//! `info` (an OperatorInfo: its name, its undo step, what it changes, its script action)
//! and, when a script gives it with plain values, a static `fields` (its script fields,
//! read by one reader). What depends on a command — spec_of, command_name, the script
//! reader and its dictionary, the menus' labels — is derived from these, and a command
//! without `info` does not compile (spec_of reads it for every alternative of Command).

namespace meshfair::app {

//! What a command is and does to the document.
struct OperatorInfo
{
    //! Its name in messages and the trace ("create set").
    std::string_view id = {};
    //! Its entry in a menu, when it has one whatever its values ("Frame all").
    std::string_view menu = {};
    //! The name of the undo step it makes; empty: it makes none.
    std::string_view label = {};
    unsigned captures = 0;         //!< the EditPart flags its undo step keeps (0: not an undo step)
    unsigned bumps = 0;            //!< the parts whose versions it bumps when done
    bool stops_run = false;        //!< a run playing is paused (its segment recorded) first
    bool waits_for_gesture = true; //!< refused while a tool's gesture is under way
    //! The script action that gives it ("create_set"); empty: no script gives it alone.
    std::string_view script = {};
    //! Another script action that gives it ("hide_set" beside "show_set").
    std::string_view script_alias = {};
    //! The script action writes a file: its failure is an output not written (exit code 3).
    bool writes = false;
    //! The script action is read by a reader of its own (script_parse.cpp's
    //! read_action overloads) rather than from `fields`: it has several forms, or reads
    //! an object.
    bool own_reader = false;
};

//! Where a script field is written: the action's own value ("create_set": "pin"), or an
//! option beside it ("name": "left ear").
enum class FieldPlace
{
    Value,
    Option,
    RequiredOption
};

//! \brief One field of a command as a script writes it. `T` is the member's type: text,
//! true/false, a number within [lo, hi] (integers too), a vector [x, y, z], or an enum
//! named by `named` (its names listed, for messages, in `choices`).
template <class C, class T>
struct Field
{
    std::string_view key; //!< the option's key (a Value field: the action's)
    T C::*member;
    FieldPlace place = FieldPlace::Value;
    std::string_view doc = {}; //!< what it holds ("the new name"), for messages and docs
    double lo = 0, hi = 0;     //!< numbers' range
    std::optional<T> (*named)(std::string_view) = nullptr; //!< enums: the value named so
    std::string_view choices = {};                         //!< enums: "a, b or c"
    bool nonzero = false;                                  //!< vectors: not [0, 0, 0]
};

//! A field of the action's own value.
template <class C, class T>
constexpr Field<C, T> value_field(T C::*member, std::string_view doc = {})
{
    return {{}, member, FieldPlace::Value, doc};
}
template <class C, class T>
constexpr Field<C, T> number_field(T C::*member, double lo, double hi,
                                   FieldPlace place = FieldPlace::Value, std::string_view key = {})
{
    return {key, member, place, {}, lo, hi};
}
template <class C, class T>
constexpr Field<C, T> enum_field(T C::*member, std::optional<T> (*named)(std::string_view),
                                 std::string_view choices)
{
    return {{}, member, FieldPlace::Value, {}, 0, 0, named, choices};
}
template <class C, class T>
constexpr Field<C, T> option_field(std::string_view key, T C::*member,
                                   FieldPlace place = FieldPlace::Option, std::string_view doc = {})
{
    return {key, member, place, doc};
}

//! A required option holding a vector that must not be zero.
template <class C, class T>
constexpr Field<C, T> nonzero_field(std::string_view key, T C::*member)
{
    return {key, member, FieldPlace::RequiredOption, "[x, y, z]", 0, 0, nullptr, {}, true};
}

//! Whether a command's script fields are given by its `fields` tuple.
template <class C>
concept HasFields = requires
{
    C::fields;
};

//! Whether a command's menu entry depends on its values (a static `menu_label_for`).
template <class C>
concept HasOwnMenuLabel = requires(const C& c)
{
    C::menu_label_for(c);
};

//! Whether a command's undo step depends on its values (a static `spec_for`).
template <class C>
concept HasOwnSpec = requires(const C& c)
{
    C::spec_for(c);
};

} // namespace meshfair::app
