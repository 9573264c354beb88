// SPDX-License-Identifier: MIT
// Copyright 2026 the MeshFair authors.
#include "app/editor/key_map.h"

#include <cctype>
#include <string>

namespace meshfair::app {

namespace {

constexpr Modifiers kNone{};
constexpr Modifiers kShift{true, false, false};
constexpr Modifiers kCtrl{false, true, false};
constexpr Modifiers kAlt{false, false, true};
constexpr Modifiers kCtrlShift{true, true, false};

KeyAction bind(int k, Modifiers mods, Command command)
{
    return {{k, mods}, std::move(command)};
}

int letter(char c)
{
    return key::Letter(c);
}

std::vector<KeyBinding> make_bindings()
{
    using namespace cmd;
    const auto tool = [](char c, ToolKind t) { return bind(letter(c), kNone, SetTool{t}); };
    const auto select = [](int k, Modifiers m, SelectionCommand c) {
        return bind(k, m, RunSelection{c});
    };
    const auto create = [](char c, ConstraintKind kind) {
        return bind(letter(c), kShift, CreateSet{kind, {}});
    };
    const auto view = [](int k, Modifiers m, StandardView v) { return bind(k, m, SetView{v}); };
    const auto toggle = [](int k, Modifiers m, DisplayToggle t) { return bind(k, m, Toggle{t}); };
    return {
        {"Left drag", "the active tool; with Navigate, orbit (turntable or trackball, see T)", {}},
        {"Alt + left drag", "orbit, whatever the tool", {}},
        {"Shift + tool", "add to the selection", {}},
        {"Ctrl + tool", "take away from the selection", {}},
        {"N / K / C / R / L",
         "tool: navigate / click / brush / rectangle / lasso",
         {tool('n', ToolKind::Navigate), tool('k', ToolKind::Click), tool('c', ToolKind::Brush),
          tool('r', ToolKind::Rectangle), tool('l', ToolKind::Lasso)}},
        {"M", "tool: drag pins to new targets in the view plane", {tool('m', ToolKind::MovePins)}},
        {"D",
         "tool: drag a normal set's arrows to turn its direction",
         {tool('d', ToolKind::AimNormals)}},
        {"O",
         "tool: paint (the smoothing brush, or a set's weight map; see the Paint panel)",
         {tool('o', ToolKind::Paint)}},
        {"V", "select vertices / faces", {bind(letter('v'), kNone, ToggleElements{})}},
        {"[ / ]",
         "brush radius smaller / larger",
         {bind(key::LeftBracket, kNone, ScaleBrushRadius{1 / 1.25}),
          bind(key::RightBracket, kNone, ScaleBrushRadius{1.25})}},
        {"Ctrl + A, Alt + A",
         "select all, select none",
         {select(letter('a'), kCtrl, SelectionCommand::All),
          select(letter('a'), kAlt, SelectionCommand::Clear)}},
        {"Ctrl + I",
         "invert the selection",
         {select(letter('i'), kCtrl, SelectionCommand::Invert)}},
        {"Ctrl + = / Ctrl + -",
         "grow / shrink the selection by a ring",
         {select(key::Equal, kCtrl, SelectionCommand::Grow),
          select(key::KeypadAdd, kCtrl, SelectionCommand::Grow),
          select(key::Minus, kCtrl, SelectionCommand::Shrink),
          select(key::KeypadSubtract, kCtrl, SelectionCommand::Shrink)}},
        {"Ctrl + L",
         "select the connected components of the selection",
         {select(letter('l'), kCtrl, SelectionCommand::Connected)}},
        {"Ctrl + B",
         "select the boundary",
         {select(letter('b'), kCtrl, SelectionCommand::Boundary)}},
        {"Shift + R / P / A / C / N",
         "new region / pin / anchor / centroid / normal set from the selection",
         {create('r', ConstraintKind::Region), create('p', ConstraintKind::Pin),
          create('a', ConstraintKind::Anchor), create('c', ConstraintKind::Centroid),
          create('n', ConstraintKind::Normal)}},
        {"Space", "play / pause live solving", {bind(key::Space, kNone, TogglePlay{})}},
        {"Enter",
         "solve: show the minimizer of the sets (the direct method)",
         {bind(key::Enter, kNone, Solve{}), bind(key::KeypadEnter, kNone, Solve{})}},
        {"Esc",
         "cancel the solver's preparation (a long factorization)",
         {bind(key::Escape, kNone, CancelPreparation{})}},
        {"E", "energy plot", {toggle(letter('e'), kNone, DisplayToggle::EnergyPlot)}},
        {"Ctrl + Z", "undo", {bind(letter('z'), kCtrl, Undo{})}},
        {"Ctrl + Shift + Z, Ctrl + Y",
         "redo",
         {bind(letter('z'), kCtrlShift, Redo{}), bind(letter('y'), kCtrl, Redo{})}},
        {"Middle drag", "orbit", {}},
        {"Right drag, Shift + middle drag", "pan", {}},
        {"Wheel", "zoom to the cursor", {}},
        {"Ctrl + middle drag", "zoom (drag up: closer)", {}},
        {"Home, numpad .",
         "frame all",
         {bind(key::Home, kNone, FrameAll{}), bind(key::KeypadDecimal, kNone, FrameAll{})}},
        {"F",
         "frame the selection (all when nothing is selected)",
         {bind(letter('f'), kNone, FrameSelection{})}},
        {"Numpad 1 / 3 / 7 (or 1 / 3 / 7)",
         "front / right / top view",
         {view(key::Keypad(1), kNone, StandardView::Front),
          view(key::Digit0 + 1, kNone, StandardView::Front),
          view(key::Keypad(3), kNone, StandardView::Right),
          view(key::Digit0 + 3, kNone, StandardView::Right),
          view(key::Keypad(7), kNone, StandardView::Top),
          view(key::Digit0 + 7, kNone, StandardView::Top)}},
        {"Ctrl + numpad 1 / 3 / 7",
         "back / left / bottom view",
         {view(key::Keypad(1), kCtrl, StandardView::Back),
          view(key::Digit0 + 1, kCtrl, StandardView::Back),
          view(key::Keypad(3), kCtrl, StandardView::Left),
          view(key::Digit0 + 3, kCtrl, StandardView::Left),
          view(key::Keypad(7), kCtrl, StandardView::Bottom),
          view(key::Digit0 + 7, kCtrl, StandardView::Bottom)}},
        {"Numpad 5 (or 5)",
         "perspective / orthographic",
         {bind(key::Keypad(5), kNone, ToggleProjection{}),
          bind(key::Digit0 + 5, kNone, ToggleProjection{})}},
        {"T", "turntable / trackball orbit", {bind(letter('t'), kNone, ToggleOrbit{})}},
        {"S", "smooth / flat shading", {toggle(letter('s'), kNone, DisplayToggle::Shading)}},
        {"W", "polygon wireframe", {toggle(letter('w'), kNone, DisplayToggle::Wireframe)}},
        {"B",
         "boundary and singular edges",
         {toggle(letter('b'), kNone, DisplayToggle::BoundaryEdges)}},
        {"P", "vertex points", {toggle(letter('p'), kNone, DisplayToggle::VertexPoints)}},
        {"Tab", "side panel", {toggle(key::Tab, kNone, DisplayToggle::SidePanel)}},
        {"F1, H",
         "this help",
         {toggle(key::F1, kNone, DisplayToggle::Help),
          toggle(letter('h'), kNone, DisplayToggle::Help)}},
        {"F12", "screenshot (PNG)", {bind(key::F12, kNone, Screenshot{})}},
        {"Ctrl + O",
         "open a mesh (or drop a file on the window)",
         {bind(letter('o'), kCtrl, ShowDialog{Dialog::OpenMesh})}},
        {"Ctrl + S",
         "save (the file it came from, in its format)",
         {bind(letter('s'), kCtrl, SaveMesh{})}},
        {"Ctrl + Shift + S",
         "save as",
         {bind(letter('s'), kCtrlShift, ShowDialog{Dialog::SaveMeshAs})}},
        {"Ctrl + Q, closing the window",
         "quit (asks first when there are unsaved changes)",
         {bind(letter('q'), kCtrl, Quit{})}},
    };
}

} // namespace

std::span<const KeyBinding> key_bindings()
{
    static const std::vector<KeyBinding> bindings = make_bindings();
    return bindings;
}

std::optional<Command> command_for_key(const KeyChord& chord)
{
    for (const KeyBinding& b : key_bindings())
        for (const KeyAction& k : b.keys)
            if (k.chord == chord)
                return k.command;
    return std::nullopt;
}

std::optional<KeyChord> key_for(const Command& command)
{
    for (const KeyBinding& b : key_bindings())
        for (const KeyAction& k : b.keys)
            if (k.command == command)
                return k.chord;
    return std::nullopt;
}

std::string chord_label(const KeyChord& chord)
{
    std::string text;
    if (chord.mods.ctrl)
        text += "Ctrl+";
    if (chord.mods.shift)
        text += "Shift+";
    if (chord.mods.alt)
        text += "Alt+";
    static const std::pair<int, const char*> named[] = {{key::Space, "Space"},
                                                        {key::Escape, "Esc"},
                                                        {key::Enter, "Enter"},
                                                        {key::Tab, "Tab"},
                                                        {key::Home, "Home"},
                                                        {key::End, "End"},
                                                        {key::Delete, "Delete"},
                                                        {key::KeypadDecimal, "Numpad ."},
                                                        {key::KeypadEnter, "Numpad Enter"}};
    for (const auto& [code, name] : named)
        if (chord.key == code)
            return text + name;
    if (chord.key >= key::F1 && chord.key <= key::F12)
        return text + "F" + std::to_string(chord.key - key::F1 + 1);
    if (chord.key >= key::Keypad0 && chord.key <= key::Keypad9)
        return text + "Numpad " + std::to_string(chord.key - key::Keypad0);
    if (chord.key > key::Space && chord.key < 127)
        return text + static_cast<char>(chord.key);
    return text + "key " + std::to_string(chord.key);
}

std::optional<KeyChord> parse_key_chord(std::string_view text)
{
    KeyChord chord;
    std::string rest(text);
    for (char& c : rest)
        c = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
    // Modifiers first, joined by '+'; the last part is the key.
    for (;;)
    {
        const size_t plus = rest.find('+', 1);
        if (plus == std::string::npos)
            break;
        const std::string m = rest.substr(0, plus);
        if (m == "shift")
            chord.mods.shift = true;
        else if (m == "ctrl" || m == "control")
            chord.mods.ctrl = true;
        else if (m == "alt")
            chord.mods.alt = true;
        else
            return std::nullopt;
        rest = rest.substr(plus + 1);
    }
    static const std::pair<const char*, int> named[] = {{"space", key::Space},
                                                        {"escape", key::Escape},
                                                        {"return", key::Enter},
                                                        {"enter", key::Enter},
                                                        {"tab", key::Tab},
                                                        {"backspace", key::Backspace},
                                                        {"delete", key::Delete},
                                                        {"home", key::Home},
                                                        {"end", key::End},
                                                        {"left", key::Left},
                                                        {"right", key::Right},
                                                        {"up", key::Up},
                                                        {"down", key::Down},
                                                        {"bracketleft", key::LeftBracket},
                                                        {"[", key::LeftBracket},
                                                        {"bracketright", key::RightBracket},
                                                        {"]", key::RightBracket},
                                                        {"equal", key::Equal},
                                                        {"=", key::Equal},
                                                        {"minus", key::Minus},
                                                        {"-", key::Minus},
                                                        {"period", key::Period},
                                                        {"kp_decimal", key::KeypadDecimal},
                                                        {"kp_add", key::KeypadAdd},
                                                        {"kp_subtract", key::KeypadSubtract}};
    for (const auto& [name, code] : named)
        if (rest == name)
        {
            chord.key = code;
            return chord;
        }
    if (rest.size() == 1 && rest[0] >= 'a' && rest[0] <= 'z')
        chord.key = key::Letter(rest[0]);
    else if (rest.size() == 1 && rest[0] >= '0' && rest[0] <= '9')
        chord.key = key::Digit0 + (rest[0] - '0');
    else if (rest.size() == 4 && rest.rfind("kp_", 0) == 0 && rest[3] >= '0' && rest[3] <= '9')
        chord.key = key::Keypad(rest[3] - '0');
    else if (rest.size() >= 2 && rest.size() <= 3 && rest[0] == 'f' &&
             rest.find_first_not_of("0123456789", 1) == std::string::npos)
    {
        // F1 to F12: at most two digits (a longer run of digits, which std::stoi would
        // throw on, names no key either).
        const int n = std::stoi(rest.substr(1));
        if (n < 1 || n > 12)
            return std::nullopt;
        chord.key = key::F(n);
    }
    else
        return std::nullopt;
    return chord;
}

} // namespace meshfair::app
