// SPDX-License-Identifier: MIT
// Copyright 2026 the MeshFair authors.
#pragma once

#include <optional>
#include <string>
#include <string_view>

#include "app/tools/navigation.h"

namespace meshfair::app {

//! \brief Key codes: GLFW's own numbers (window.cpp checks that they agree), so that the
//! window passes its keys through unchanged and scripts name the same keys. Printable keys
//! are their upper-case ASCII codes.
namespace key {
inline constexpr int Space = 32, Apostrophe = 39, Comma = 44, Minus = 45, Period = 46, Slash = 47,
                     Digit0 = 48, Digit9 = 57, Semicolon = 59, Equal = 61, A = 65, Z = 90,
                     LeftBracket = 91, Backslash = 92, RightBracket = 93;
inline constexpr int Escape = 256, Enter = 257, Tab = 258, Backspace = 259, Insert = 260,
                     Delete = 261, Right = 262, Left = 263, Down = 264, Up = 265, PageUp = 266,
                     PageDown = 267, Home = 268, End = 269, F1 = 290, F12 = 301, Keypad0 = 320,
                     Keypad9 = 329, KeypadDecimal = 330, KeypadDivide = 331, KeypadMultiply = 332,
                     KeypadSubtract = 333, KeypadAdd = 334, KeypadEnter = 335, KeypadEqual = 336,
                     LeftShift = 340, LeftControl = 341, LeftAlt = 342, LeftSuper = 343,
                     RightShift = 344, RightControl = 345, RightAlt = 346, RightSuper = 347,
                     Last = 348;
inline constexpr int F(int n)
{
    return F1 + n - 1;
}
inline constexpr int Letter(char c)
{
    return A + (c - 'a');
}
inline constexpr int Keypad(int digit)
{
    return Keypad0 + digit;
}
} // namespace key

//! \brief "ctrl+shift+z", "space", "f1", "kp_5", "bracketleft" style names (xdotool's and
//! scripts'), parsed into a key code and modifiers; nullopt for a name it does not know.
struct KeyChord
{
    int key = 0;
    Modifiers mods;
    bool operator==(const KeyChord& o) const
    {
        return key == o.key && mods.shift == o.mods.shift && mods.ctrl == o.mods.ctrl &&
               mods.alt == o.mods.alt;
    }
};
std::optional<KeyChord> parse_key_chord(std::string_view text);

//! \brief One raw input event, as the window's callbacks receive it or a script gives it.
//! Positions are framebuffer pixels, (0, 0) the top-left corner of the window.
struct InputEvent
{
    enum class Type
    {
        MouseMove,    //!< x, y
        MousePress,   //!< button, mods, x, y
        MouseRelease, //!< button, x, y
        Scroll,       //!< wheel notches in `amount`, x, y
        KeyPress,     //!< key, mods (repeats too)
        KeyRelease,   //!< key, mods
        Char          //!< a typed character (Unicode code point) in `key`
    };
    Type type = Type::MouseMove;
    double x = 0, y = 0;
    MouseButton button = MouseButton::Left;
    Modifiers mods;
    int key = 0;
    double amount = 0;
};

} // namespace meshfair::app
