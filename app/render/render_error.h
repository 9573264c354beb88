// SPDX-License-Identifier: MIT
// Copyright 2026 the MeshFair authors.
#pragma once

#include <stdexcept>
#include <string>

namespace meshfair::app {

//! A context that cannot be created, a shader that does not compile, a GL error after a
//! renderer call: what the viewer reports and exits on (or falls back from).
class RenderError : public std::runtime_error
{
public:
    explicit RenderError(const std::string& what) : std::runtime_error(what) {}
};

} // namespace meshfair::app
