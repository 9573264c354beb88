// SPDX-License-Identifier: MIT
// Copyright 2026 the MeshFair authors.
#include "app/render/image.h"

#include <algorithm>
#include <cstdlib>
#include <string_view>

#include <stb/stb_image.h>
#include <stb/stb_image_write.h>

#include "core/errors.h"
#include "core/io/io.h"

namespace meshfair::app {

void write_png(const Image& image, const std::string& path)
{
    std::string bytes;
    const auto append = [](void* context, void* data, int size) {
        static_cast<std::string*>(context)->append(static_cast<const char*>(data),
                                                   static_cast<size_t>(size));
    };
    if (image.width <= 0 || image.height <= 0 ||
        stbi_write_png_to_func(append, &bytes, image.width, image.height, 4, image.rgba.data(),
                               4 * image.width) == 0)
        throw WriteError("cannot write '" + path + "': PNG encoding failed");
    io::write_file_atomically(path, bytes);
}

Image read_png(const std::string& path)
{
    const std::string bytes = io::read_file(path);
    int w = 0, h = 0, channels = 0;
    stbi_uc* pixels = stbi_load_from_memory(reinterpret_cast<const stbi_uc*>(bytes.data()),
                                            static_cast<int>(bytes.size()), &w, &h, &channels, 4);
    if (pixels == nullptr)
        throw InvalidInputError("'" + path + "': not a PNG image (" + stbi_failure_reason() + ")");
    Image image{w, h, std::vector<std::uint8_t>(pixels, pixels + size_t{4} * w * h)};
    stbi_image_free(pixels);
    return image;
}

ImageDifference compare_images(const Image& a, const Image& b, int tolerance)
{
    ImageDifference d;
    d.same_size = a.width == b.width && a.height == b.height && a.rgba.size() == b.rgba.size();
    if (!d.same_size)
        return d;
    for (size_t p = 0; p < a.rgba.size(); p += 4)
    {
        int worst = 0;
        for (size_t c = 0; c < 4; ++c)
            worst = std::max(worst, std::abs(int(a.rgba[p + c]) - int(b.rgba[p + c])));
        d.max_channel_difference = std::max(d.max_channel_difference, worst);
        d.pixels_over_tolerance += worst > tolerance;
    }
    const auto pixels = static_cast<double>(a.rgba.size() / 4);
    d.fraction_over_tolerance =
        pixels > 0 ? static_cast<double>(d.pixels_over_tolerance) / pixels : 0;
    return d;
}

Image difference_image(const Image& a, const Image& b, int tolerance)
{
    Image out{std::max(a.width, b.width), std::max(a.height, b.height), {}};
    out.rgba.assign(size_t{4} * out.width * out.height, 0);
    for (int y = 0; y < out.height; ++y)
        for (int x = 0; x < out.width; ++x)
        {
            std::uint8_t* o = &out.rgba[4 * (size_t(y) * out.width + x)];
            o[3] = 255;
            if (x >= a.width || y >= a.height || x >= b.width || y >= b.height)
            {
                o[0] = 255; // outside one of them: a size mismatch shows in red
                continue;
            }
            const std::uint8_t* p = &a.rgba[4 * (size_t(y) * a.width + x)];
            const std::uint8_t* q = &b.rgba[4 * (size_t(y) * b.width + x)];
            int worst = 0;
            for (int c = 0; c < 4; ++c)
                worst = std::max(worst, std::abs(int(p[c]) - int(q[c])));
            if (worst > tolerance)
                o[0] = 255;
            else
                o[0] = o[1] = o[2] = static_cast<std::uint8_t>(std::min(255, worst * 16));
        }
    return out;
}

} // namespace meshfair::app
