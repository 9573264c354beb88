// SPDX-License-Identifier: MIT
// Copyright 2026 the MeshFair authors.
#pragma once

#include <cstddef>
#include <span>
#include <string>
#include <string_view>
#include <vector>

#include "core/mesh/mesh.h"

namespace meshfair::io {

//! PLY's eight value types. Attribute values are held as doubles, which represent every
//! value of each of them exactly; the type is what a writer stores them as.
enum class ValueType
{
    Int8,
    UInt8,
    Int16,
    UInt16,
    Int32,
    UInt32,
    Float32,
    Float64
};

//! PLY's name of the type: "char", "uchar", ..., "float", "double".
std::string_view value_type_name(ValueType type);
//! Bytes of one value in a binary file.
size_t value_type_size(ValueType type);
bool is_integer_type(ValueType type);

//! One named value per row (a PLY scalar property), or one list per row.
struct Property
{
    std::string name;
    ValueType type = ValueType::Float64; //!< of the value, or of a list's items
    bool is_list = false;
    ValueType count_type = ValueType::UInt8; //!< lists only: the type of each row's count
    std::vector<double> values;              //!< a value per row, or every list's items
    std::vector<Index> offsets; //!< lists only: row r is values[offsets[r], offsets[r+1])

    friend bool operator==(const Property&, const Property&) = default;
};

//! A table with `count` rows: the extra properties of the vertices or of the faces, or a
//! whole element MeshFair does not interpret (a PLY's edges, materials, cameras).
struct Element
{
    std::string name;
    Index count = 0;
    std::vector<Property> properties;

    //! The first scalar property with one of these names (in their order), or nullptr.
    const Property* find(std::span<const std::string_view> names) const;
    const Property* find(std::string_view one) const { return find(std::span(&one, 1)); }

    friend bool operator==(const Element&, const Element&) = default;
};

//! Values that face corners share through one index per corner: an OBJ's texture
//! coordinates (vt) or normals (vn).
struct CornerValues
{
    int dimension = 0;          //!< values per entry: vt 1 to 3, vn 3
    std::vector<double> values; //!< dimension values per entry
    //! One entry index per corner of the mesh, kInvalidIndex at the corners of a face that
    //! has none; empty when no face has any.
    std::vector<Index> corners;

    bool empty() const { return corners.empty(); }
    Index entry_count() const
    {
        return dimension == 0 ? 0
                              : static_cast<Index>(values.size() / static_cast<size_t>(dimension));
    }
    friend bool operator==(const CornerValues&, const CornerValues&) = default;
};

//! An OBJ statement that applies to the faces after it: a group (g), object (o),
//! smoothing group (s), material (usemtl) or material library (mtllib).
struct ObjStatement
{
    Index before_face = 0; //!< the number of faces before it in the file
    std::string text;      //!< keyword and arguments, single-spaced, comment removed

    friend bool operator==(const ObjStatement&, const ObjStatement&) = default;
};

//! \brief Everything a mesh file holds besides positions and faces, in the file's
//! numbering, so that a smoothed mesh is written back with it.
//!
//! Smoothing moves vertices and keeps the faces, so every table here stays valid for the
//! smoothed positions: texture coordinates and colours are written unchanged, normals are
//! recomputed from the new positions (recompute_normals) unless kept on request.
//!
//! Names of the vertex and face properties follow PLY's customs whatever the file's
//! format, so any writer finds them: colours `red green blue [alpha]`, normals `nx ny
//! nz`, per-vertex texture coordinates `texture_u texture_v` (PLY files may also say
//! `u v` or `s t`), per-corner texture coordinates a face list `texcoord` (u v per
//! corner, as MeshLab writes them), a binary STL's two attribute bytes `stl_attribute`.
struct MeshAttributes
{
    Element vertex{"vertex", 0, {}};      //!< one row per vertex (properties beside x y z)
    Element face{"face", 0, {}};          //!< one row per face (properties beside the indices)
    std::vector<Element> other_elements;  //!< a PLY's other elements, in file order
    CornerValues texcoords;               //!< OBJ vt, one index per corner
    CornerValues normals;                 //!< OBJ vn, one index per corner
    std::vector<ObjStatement> statements; //!< OBJ g, o, s, usemtl, mtllib
    std::vector<std::string> comments;    //!< a PLY header's comment and obj_info lines

    //! True when the file held nothing beyond positions and faces.
    bool empty() const;
    friend bool operator==(const MeshAttributes&, const MeshAttributes&) = default;
};

//! Names of the properties with a meaning, in the orders writers use.
inline constexpr std::string_view kRed[] = {"red", "diffuse_red", "r"};
inline constexpr std::string_view kGreen[] = {"green", "diffuse_green", "g"};
inline constexpr std::string_view kBlue[] = {"blue", "diffuse_blue", "b"};
inline constexpr std::string_view kAlpha[] = {"alpha", "diffuse_alpha", "a"};
inline constexpr std::string_view kNormalX[] = {"nx", "normal_x"};
inline constexpr std::string_view kNormalY[] = {"ny", "normal_y"};
inline constexpr std::string_view kNormalZ[] = {"nz", "normal_z"};
inline constexpr std::string_view kTextureU[] = {"texture_u", "u", "s", "texture_s"};
inline constexpr std::string_view kTextureV[] = {"texture_v", "v", "t", "texture_t"};
inline constexpr std::string_view kCornerTexcoords = "texcoord";
inline constexpr std::string_view kStlAttribute = "stl_attribute";

//! The three properties of a colour, a normal or a texture coordinate pair found in a
//! table (null when any is missing).
struct Channels
{
    const Property* rgb[3] = {nullptr, nullptr, nullptr};
    const Property* alpha = nullptr;
    const Property* normal[3] = {nullptr, nullptr, nullptr};
    const Property* uv[2] = {nullptr, nullptr};
    bool has_colour() const { return rgb[0] != nullptr; }
    bool has_normal() const { return normal[0] != nullptr; }
    bool has_uv() const { return uv[0] != nullptr; }
    //! True for a property that is one of the channels found.
    bool contains(const Property* p) const;
};
Channels find_channels(const Element& table);

//! \brief Checks that the attributes fit the mesh: a row per vertex and per face, list
//! offsets consistent, corner indices within their entries.
//! \throw InvalidInputError naming the first table that does not fit.
void check_attributes(const Mesh& mesh, const MeshAttributes& attributes);

//! \brief Replaces every normal by the one of `mesh`'s positions: vertex normals (`nx ny
//! nz` of the vertex table) by the normalized sum of the area vectors (face_area_vector)
//! of the faces around the vertex; face normals (`nx ny nz` of the face table) by
//! face_normal; an OBJ's per-corner normals by the normalized sum of the area vectors of
//! the faces whose corners share the vertex and the normal index, so that the hard edges
//! the file drew (different normals at one vertex) stay hard. Entries are renumbered in
//! order of first use. A normal with no face of positive area around it keeps its value.
void recompute_normals(const Mesh& mesh, MeshAttributes& attributes);

//! \brief Per-corner values as one entry per vertex, when every corner of each vertex
//! has the same values (vertices in no face get zeros): what a format with a value per
//! vertex can hold. Returns false (and leaves `per_vertex` undefined) when some vertex
//! has different values at different corners, or some corner has none.
bool values_per_vertex(const Mesh& mesh, const CornerValues& corners,
                       std::vector<double>& per_vertex);

//! \brief One normal per vertex from per-corner normals: the corners' normal where they
//! agree, else the normalized mean of the normals of its corners (corners without one
//! ignored; zeros for a vertex with none). `hard` receives the number of vertices whose
//! corners have different normals (the hard edges an OBJ draws).
std::vector<double> per_vertex_normals(const Mesh& mesh, const CornerValues& normals,
                                       std::int64_t& hard);

//! The note a format with one normal per vertex gives for `hard` > 0 such vertices.
std::string hard_edges_note(const std::string& format, std::int64_t hard);

//! \brief The texture coordinates as per-corner values, from wherever the attributes hold
//! them: an OBJ's vt, a face list `texcoord` (2 values per corner), or the vertex table's
//! `texture_u texture_v`. Empty when there are none. `source`, when given, receives the
//! property or list used (nullptr for an OBJ's vt).
CornerValues corner_texcoords(const Mesh& mesh, const MeshAttributes& attributes,
                              const Property** source = nullptr);

//! \brief The normals as per-corner values: an OBJ's vn, or the vertex table's `nx ny nz`.
CornerValues corner_normals(const Mesh& mesh, const MeshAttributes& attributes);

//! True when every value is finite (text formats other than PLY hold no NaN or infinity).
bool all_finite(std::span<const double> values);

//! The note for values a text format cannot hold: "OBJ cannot hold NaN or infinite values:
//! the normals are not written".
std::string nonfinite_note(const std::string& format, const std::string& what);

//! How many of a file's other elements describe_attributes and the notes of what a format
//! cannot hold name one by one; the rest are counted.
inline constexpr size_t kElementsListed = 8;

//! One line per kind of attribute, for `info` and reports: "vertex colours (red green
//! blue: uchar)", "texture coordinates: 3225 vt on 12000 corners", ...; other elements one
//! line each up to kElementsListed, then "N more elements (R rows, P properties in all)".
std::vector<std::string> describe_attributes(const MeshAttributes& attributes);

//! \brief What a writer leaves out, gathered into one note per kind:
//! "OBJ cannot hold the vertex properties 'quality', 'flags'; they are not written".
class Unwritten
{
public:
    explicit Unwritten(std::string format) : format_(std::move(format)) {}
    void add(const std::string& kind, const std::string& name);
    //! Every property of `table` that is not in `written`, as "<name> properties 'p'".
    void add_table(const Element& table, const std::vector<const Property*>& written);
    //! Every element of `elements`, as "elements 'edge' (12 rows)".
    void add_elements(const std::vector<Element>& elements);
    //! Appends the notes to `notes`.
    void flush(std::vector<std::string>& notes) const;

private:
    std::string format_;
    std::vector<std::pair<std::string, std::vector<std::string>>> kinds_;
};

} // namespace meshfair::io
