// SPDX-License-Identifier: MIT
// Copyright 2026 the MeshFair authors.
#pragma once

#include <bit>
#include <cstdint>
#include <cstring>
#include <string>
#include <string_view>
#include <type_traits>

#include "core/errors.h"

namespace meshfair::io {

enum class ByteOrder
{
    Little,
    Big
};

//! \brief Bounds-checked reads of fixed-size numbers from binary data held in memory.
//!
//! Every failure names the file, the byte offset, and the element, row and property
//! being read (set them with at()) so that a truncated or lying file is reported
//! precisely.
class ByteReader
{
public:
    ByteReader(std::string_view data, std::string file, size_t offset = 0)
        : data_(data), file_(std::move(file)), pos_(offset)
    {
    }

    //! Names what the next reads belong to, for error messages.
    void at(std::string element, std::int64_t row, std::string property)
    {
        element_ = std::move(element);
        row_ = row;
        property_ = std::move(property);
    }

    size_t offset() const { return pos_; }
    size_t remaining() const { return data_.size() - pos_; }
    bool at_end() const { return pos_ >= data_.size(); }
    //! The bytes not read yet.
    std::string_view rest() const { return data_.substr(pos_); }

    template <typename T>
    T read(ByteOrder order)
    {
        static_assert(std::is_arithmetic_v<T>);
        if (remaining() < sizeof(T))
            fail("file ends inside this value (needs " + std::to_string(sizeof(T)) + " bytes, " +
                 std::to_string(remaining()) + " left)");
        unsigned char bytes[sizeof(T)];
        std::memcpy(bytes, data_.data() + pos_, sizeof(T));
        if ((order == ByteOrder::Little) != (std::endian::native == std::endian::little))
            for (size_t k = 0; k < sizeof(T) / 2; ++k)
                std::swap(bytes[k], bytes[sizeof(T) - 1 - k]);
        T value;
        std::memcpy(&value, bytes, sizeof(T));
        pos_ += sizeof(T);
        return value;
    }

    void skip(size_t bytes)
    {
        if (remaining() < bytes)
            fail("file ends inside this element (needs " + std::to_string(bytes) + " more bytes, " +
                 std::to_string(remaining()) + " left)");
        pos_ += bytes;
    }

    SourceLocation here() const
    {
        SourceLocation loc;
        loc.file = file_;
        loc.byte_offset = static_cast<std::int64_t>(pos_);
        loc.element = element_;
        loc.row = row_;
        loc.property = property_;
        return loc;
    }

    [[noreturn]] void fail(const std::string& message) const { throw FormatError(here(), message); }

private:
    std::string_view data_;
    std::string file_;
    size_t pos_ = 0;
    std::string element_;
    std::int64_t row_ = -1;
    std::string property_;
};

} // namespace meshfair::io
