// SPDX-License-Identifier: MIT
// Copyright 2026 the MeshFair authors.
#include "app/render/camera.h"

#include <algorithm>
#include <cmath>

#include <glm/gtc/matrix_transform.hpp>
#include <nlohmann/json.hpp>

#include "core/errors.h"
#include "core/io/checked_json.h"
#include "core/parallel/parallel.h"

namespace meshfair::app {

namespace {

constexpr double kPi = 3.14159265358979323846;

// A point of the window on Shoemake's arcball: the unit sphere inscribed in the window,
// and beyond its rim the rim itself.
glm::dvec3 arcball_point(double x, double y, int width, int height)
{
    const double s = std::max(1, std::min(width, height));
    glm::dvec3 p{(2 * x - width) / s, (height - 2 * y) / s, 0};
    const double d2 = p.x * p.x + p.y * p.y;
    if (d2 < 1)
        p.z = std::sqrt(1 - d2);
    else
        p /= std::sqrt(d2);
    return p;
}

} // namespace

double Box3::radius() const
{
    return empty() ? 1.0 : std::max(0.5 * glm::length(hi - lo), 1e-9);
}

glm::dvec3 Camera::forward() const
{
    return rotation * glm::dvec3(0, 0, -1);
}

glm::dvec3 Camera::up() const
{
    return rotation * glm::dvec3(0, 1, 0);
}

glm::dvec3 Camera::right() const
{
    return rotation * glm::dvec3(1, 0, 0);
}

glm::dvec3 Camera::eye() const
{
    return target - distance * forward();
}

double Camera::near_plane() const
{
    const double depth = glm::dot(scene_center - eye(), forward());
    const double near = depth - scene_radius;
    // Orthographic depth may be negative: what is behind the eye is still in view.
    return projection == Projection::Orthographic ? near : std::max(near, 1e-4 * scene_radius);
}

double Camera::far_plane() const
{
    const double depth = glm::dot(scene_center - eye(), forward());
    return std::max(depth + scene_radius, near_plane() + 1e-3 * scene_radius);
}

double Camera::view_height() const
{
    return 2 * distance * std::tan(0.5 * glm::radians(fov_y_degrees));
}

glm::dmat4 Camera::view_matrix() const
{
    return glm::lookAt(eye(), target, up());
}

glm::dmat4 Camera::projection_matrix(double aspect) const
{
    if (projection == Projection::Perspective)
        return glm::perspective(glm::radians(fov_y_degrees), aspect, near_plane(), far_plane());
    const double h = 0.5 * view_height();
    return glm::ortho(-h * aspect, h * aspect, -h, h, near_plane(), far_plane());
}

glm::dvec3 Camera::project(const glm::dvec3& p, int width, int height) const
{
    const glm::dvec4 clip =
        projection_matrix(double(width) / height) * view_matrix() * glm::dvec4(p, 1);
    const glm::dvec3 ndc = glm::dvec3(clip) / clip.w;
    return {(ndc.x + 1) * 0.5 * width, (1 - ndc.y) * 0.5 * height, (ndc.z + 1) * 0.5};
}

glm::dvec3 Camera::unproject(const glm::dvec3& window, int width, int height) const
{
    const glm::dvec4 ndc{2 * window.x / width - 1, 1 - 2 * window.y / height, 2 * window.z - 1, 1};
    const glm::dvec4 world =
        glm::inverse(projection_matrix(double(width) / height) * view_matrix()) * ndc;
    return glm::dvec3(world) / world.w;
}

void Camera::frame(const Box3& box, double aspect)
{
    scene_center = box.empty() ? glm::dvec3(0.0) : box.center();
    scene_radius = box.radius();
    target = scene_center;
    const double r = 1.05 * scene_radius;
    const double half_y = 0.5 * glm::radians(fov_y_degrees);
    if (projection == Projection::Perspective)
    {
        // The sphere fits when its tangent cone's half angle is the narrower half field.
        const double half_x = std::atan(std::tan(half_y) * aspect);
        distance = r / std::sin(std::min(half_y, half_x));
    }
    else
    {
        const double height = 2 * r * std::max(1.0, 1.0 / aspect);
        distance = height / (2 * std::tan(half_y));
        // Keep the eye outside the sphere, so that a switch to perspective sees it all.
        distance = std::max(distance, 2 * r);
    }
}

void Camera::frame(const Box3& part, const Box3& scene, double aspect)
{
    frame(part, aspect);
    scene_center = scene.empty() ? glm::dvec3(0.0) : scene.center();
    scene_radius = scene.radius();
}

std::string_view up_axis_name(UpAxis axis)
{
    static constexpr std::string_view names[] = {"+x", "-x", "+y", "-y", "+z", "-z"};
    return names[static_cast<int>(axis)];
}

std::optional<Projection> projection_named(std::string_view name)
{
    if (name == "perspective")
        return Projection::Perspective;
    if (name == "orthographic")
        return Projection::Orthographic;
    return std::nullopt;
}

std::optional<UpAxis> up_axis_named(std::string_view name)
{
    for (const UpAxis a : kUpAxes)
        if (name == up_axis_name(a) ||
            (!name.empty() && name[0] != '-' && "+" + std::string(name) == up_axis_name(a)))
            return a;
    return std::nullopt;
}

namespace {

// The turn that takes world +y to the up axis: the standard views of a +y-up world, turned
// so (for +z, a quarter about x: the front view then looks along +y, as Blender's does).
glm::dquat up_turn(UpAxis axis)
{
    const glm::dvec3 x{1, 0, 0}, z{0, 0, 1};
    switch (axis)
    {
        case UpAxis::X:
            return glm::angleAxis(-0.5 * kPi, z);
        case UpAxis::NegX:
            return glm::angleAxis(0.5 * kPi, z);
        case UpAxis::Y:
            break;
        case UpAxis::NegY:
            return glm::angleAxis(kPi, z);
        case UpAxis::Z:
            return glm::angleAxis(0.5 * kPi, x);
        case UpAxis::NegZ:
            return glm::angleAxis(-0.5 * kPi, x);
    }
    return glm::dquat(1, 0, 0, 0);
}

} // namespace

glm::dvec3 Camera::world_up() const
{
    return up_turn(up_axis) * glm::dvec3(0, 1, 0);
}

void Camera::set_view(StandardView view)
{
    const glm::dvec3 y{0, 1, 0}, x{1, 0, 0};
    switch (view)
    {
        case StandardView::Front:
            rotation = glm::dquat(1, 0, 0, 0);
            break;
        case StandardView::Back:
            rotation = glm::angleAxis(kPi, y);
            break;
        case StandardView::Right:
            rotation = glm::angleAxis(0.5 * kPi, y);
            break;
        case StandardView::Left:
            rotation = glm::angleAxis(-0.5 * kPi, y);
            break;
        case StandardView::Top:
            rotation = glm::angleAxis(-0.5 * kPi, x);
            break;
        case StandardView::Bottom:
            rotation = glm::angleAxis(0.5 * kPi, x);
            break;
    }
    // With another axis up, the same views of the world turned to it.
    rotation = up_turn(up_axis) * rotation;
}

void Camera::orbit(OrbitStyle style, double x0, double y0, double x1, double y1, int width,
                   int height)
{
    if (style == OrbitStyle::Turntable)
    {
        const double per_px = kPi / std::max(height, 1);
        const double yaw = -(x1 - x0) * per_px, pitch = -(y1 - y0) * per_px;
        rotation =
            glm::angleAxis(yaw, world_up()) * rotation * glm::angleAxis(pitch, glm::dvec3(1, 0, 0));
    }
    else
    {
        const glm::dvec3 a = arcball_point(x0, y0, width, height);
        const glm::dvec3 b = arcball_point(x1, y1, width, height);
        const glm::dvec3 axis = glm::cross(a, b);
        const double len = glm::length(axis);
        if (len < 1e-12)
            return;
        const double angle = std::atan2(len, glm::dot(a, b));
        // The scene turns with the mouse, so the camera turns the other way, about the
        // axis expressed in the camera's frame.
        rotation = rotation * glm::angleAxis(-angle, axis / len);
    }
    rotation = glm::normalize(rotation);
}

void Camera::pan(double dx_px, double dy_px, int /*width*/, int height)
{
    const double per_px = view_height() / std::max(height, 1);
    target += (-dx_px * right() + dy_px * up()) * per_px;
}

void Camera::zoom(double factor, double x_px, double y_px, int width, int height)
{
    const double per_px = view_height() / std::max(height, 1);
    const glm::dvec3 under_cursor =
        target + ((x_px - 0.5 * width) * right() + (0.5 * height - y_px) * up()) * per_px;
    distance *= factor;
    target = under_cursor + (target - under_cursor) * factor;
}

std::vector<ScreenPoint> project_points(const Camera& camera, std::span<const float> positions,
                                        int width, int height)
{
    // One matrix for all: project() would rebuild it for every point.
    const glm::dmat4 m =
        camera.projection_matrix(double(width) / std::max(height, 1)) * camera.view_matrix();
    std::vector<ScreenPoint> out(positions.size() / 3);
    parallel_for(static_cast<Index>(out.size()), [&](Index i) {
        const size_t k = 3 * static_cast<size_t>(i);
        const glm::dvec4 clip = m * glm::dvec4(positions[k], positions[k + 1], positions[k + 2], 1);
        if (clip.w <= 0)
        {
            out[static_cast<size_t>(i)] = {0, 0, -1}; // behind the eye
            return;
        }
        const glm::dvec3 ndc = glm::dvec3(clip) / clip.w;
        out[static_cast<size_t>(i)] = {(ndc.x + 1) * 0.5 * width, (1 - ndc.y) * 0.5 * height,
                                       (ndc.z + 1) * 0.5};
    });
    return out;
}

std::string to_json(const Camera& c)
{
    const nlohmann::json j = {
        {"target", {c.target.x, c.target.y, c.target.z}},
        {"distance", c.distance},
        {"rotation", {c.rotation.w, c.rotation.x, c.rotation.y, c.rotation.z}},
        {"projection", c.projection == Projection::Perspective ? "perspective" : "orthographic"},
        {"fov_y_degrees", c.fov_y_degrees},
        {"scene_center", {c.scene_center.x, c.scene_center.y, c.scene_center.z}},
        {"scene_radius", c.scene_radius},
        {"up", std::string(up_axis_name(c.up_axis))},
    };
    return j.dump(2) + "\n";
}

namespace {

template <int N>
glm::vec<N, double> vector_field(const CheckedJson& j)
{
    if (!j.is_array() || j.size() != N)
        j.fail("must be an array of " + std::to_string(N) + " numbers");
    glm::vec<N, double> v;
    for (int k = 0; k < N; ++k)
        v[k] = j.at(static_cast<size_t>(k)).number();
    return v;
}

// A view's field that must be > 0: refused in the view file's words.
double positive_field(const CheckedJson& j)
{
    const double v = j.number();
    if (v <= 0)
        j.fail("must be positive");
    return v;
}

Camera read_view(const CheckedJson& j, const Box3* scene)
{
    for (const auto& [key, value] : j.members())
        if (key != "target" && key != "distance" && key != "rotation" && key != "projection" &&
            key != "fov_y_degrees" && key != "scene_center" && key != "scene_radius" && key != "up")
            value.fail("is unknown");
    Camera c;
    if (const auto target = j.find("target"))
        c.target = vector_field<3>(*target);
    if (const auto distance = j.find("distance"))
        c.distance = positive_field(*distance);
    if (const auto rotation = j.find("rotation"))
    {
        const glm::dvec4 q = vector_field<4>(*rotation);
        if (glm::length(q) < 1e-9)
            rotation->fail("must be a non-zero quaternion (w x y z)");
        c.rotation = glm::normalize(glm::dquat(q.x, q.y, q.z, q.w));
    }
    if (const auto projection = j.find("projection"))
        c.projection = projection->choice<Projection>(
            {{"perspective", Projection::Perspective}, {"orthographic", Projection::Orthographic}});
    if (const auto fov = j.find("fov_y_degrees"))
    {
        c.fov_y_degrees = fov->number();
        if (c.fov_y_degrees <= 0 || c.fov_y_degrees >= 180)
            fov->fail("must be in (0, 180)");
    }
    if (scene != nullptr)
    {
        c.scene_center = scene->center();
        c.scene_radius = scene->radius();
    }
    if (const auto up = j.find("up"))
    {
        const std::optional<UpAxis> axis =
            up->is_string() ? up_axis_named(up->text()) : std::nullopt;
        if (!axis)
            up->fail("must be \"+x\", \"-x\", \"+y\", \"-y\", \"+z\" or \"-z\"");
        c.up_axis = *axis;
    }
    if (scene != nullptr && !scene->empty() && (!j.has("target") || !j.has("distance")))
    {
        // A view that says how to look but not at what (written by hand: `{"up": "z"}`
        // alone): the mesh framed, as Home frames it, for what the file leaves out; the
        // default target and distance would put the eye anywhere, inside the mesh too.
        Camera framed = c;
        framed.frame(*scene, 1.0);
        if (!j.has("target"))
            c.target = framed.target;
        if (!j.has("distance"))
            c.distance = framed.distance;
    }
    if (const auto center = j.find("scene_center"))
        c.scene_center = vector_field<3>(*center);
    if (const auto radius = j.find("scene_radius"))
        c.scene_radius = positive_field(*radius);
    return c;
}

} // namespace

Camera camera_from_json(const std::string& text, const std::string& name, const Box3* scene)
{
    // A view file's errors keep their words: "'v.json': view field 'distance' must be
    // positive", "'v.json': not JSON: at line 1, column 15: ...".
    try
    {
        const CheckedJson j = CheckedJson::parse(text, name);
        if (!j.is_object())
            throw InvalidInputError("'" + name + "': a view must be a JSON object");
        return read_view(j, scene);
    }
    catch (const JsonValueError& e)
    {
        throw InvalidInputError("'" + name + "': view field '" + e.path() + "' " + e.why());
    }
    catch (const JsonSyntaxError& e)
    {
        throw InvalidInputError("'" + name + "': not JSON: at line " + std::to_string(e.line()) +
                                ", column " + std::to_string(e.column()) + ": " + e.why());
    }
}

} // namespace meshfair::app
