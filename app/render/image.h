// SPDX-License-Identifier: MIT
// Copyright 2026 the MeshFair authors.
#pragma once

#include <cstdint>
#include <string>
#include <vector>

namespace meshfair::app {

//! 8-bit RGBA pixels, rows top to bottom.
struct Image
{
    int width = 0;
    int height = 0;
    std::vector<std::uint8_t> rgba; //!< 4 width height bytes
};

//! \brief Writes a PNG (stb's writer) atomically: a temporary file renamed over `path`, so
//! an existing file is either kept or replaced whole.
//! \throw WriteError naming the file.
void write_png(const Image& image, const std::string& path);

//! \brief Reads a PNG as RGBA.
//! \throw InvalidInputError naming the file.
Image read_png(const std::string& path);

//! How two images differ: over pixels, the largest per-channel difference and how many
//! pixels differ by more than the tolerance in any channel.
struct ImageDifference
{
    bool same_size = false;
    int max_channel_difference = 0;
    std::int64_t pixels_over_tolerance = 0;
    double fraction_over_tolerance = 0; //!< of all pixels
};

ImageDifference compare_images(const Image& a, const Image& b, int channel_tolerance);

//! A picture of the difference: black where equal, brighter with the difference, and
//! red where it exceeds the tolerance.
Image difference_image(const Image& a, const Image& b, int channel_tolerance);

} // namespace meshfair::app
