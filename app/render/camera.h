// SPDX-License-Identifier: MIT
// Copyright 2026 the MeshFair authors.
#pragma once

#include <optional>
#include <span>
#include <string>
#include <string_view>
#include <vector>

#include <glm/glm.hpp>
#include <glm/gtc/quaternion.hpp>

#include "core/select/screen_select.h"

namespace meshfair::app {

//! An axis-aligned box; empty when lo > hi on an axis.
struct Box3
{
    glm::dvec3 lo{1e300}, hi{-1e300};
    bool empty() const { return lo.x > hi.x; }
    void add(const glm::dvec3& p)
    {
        lo = glm::min(lo, p);
        hi = glm::max(hi, p);
    }
    glm::dvec3 center() const { return 0.5 * (lo + hi); }
    //! Radius of the sphere around the box (half its diagonal), at least 1e-9.
    double radius() const;
};

enum class Projection
{
    Perspective,
    Orthographic
};
//! "perspective" or "orthographic".
std::optional<Projection> projection_named(std::string_view name);

//! \brief Which world direction is up: +y (most viewers), +z (scanners, CAD, Blender), or
//! any other axis either way (a scan made lying down, or upside down).
enum class UpAxis
{
    X,
    NegX,
    Y,
    NegY,
    Z,
    NegZ
};
//! Every up axis, in menu order.
inline constexpr UpAxis kUpAxes[] = {UpAxis::X,    UpAxis::NegX, UpAxis::Y,
                                     UpAxis::NegY, UpAxis::Z,    UpAxis::NegZ};
//! "+x", "-x", "+y", "-y", "+z", "-z": files' and scripts' word.
std::string_view up_axis_name(UpAxis axis);
//! The axis of a name (also "x", "y", "z" for the + directions); nullopt for another word.
std::optional<UpAxis> up_axis_named(std::string_view name);

enum class OrbitStyle
{
    Turntable, //!< yaw about the world's up axis (Camera::up_axis), pitch about the view's right
               //!< axis
    Trackball  //!< free rotation about the axis under the mouse motion
};

//! The standard views of the numeric keypad (Blender's layout: 1 front, 3 right, 7 top;
//! with Ctrl the opposite side).
enum class StandardView
{
    Front,
    Back,
    Right,
    Left,
    Top,
    Bottom
};

//! \brief A camera orbiting a target point: what a view shows, independent of the window
//! (pixel sizes are passed in). Pure maths, no GL; saved and loaded as JSON (to_json,
//! camera_from_json) for reproducible screenshots.
//!
//! Conventions: world +y is up, or another axis (up_axis); the camera looks along its local -z;
//! window coordinates are pixels with (0, 0) at the top-left corner and y down; depth is 0 at the
//! near plane and 1 at the far plane, as OpenGL's default depth range writes it.
struct Camera
{
    glm::dvec3 target{0.0};          //!< the point orbited about
    double distance = 1;             //!< from the eye to the target, > 0
    glm::dquat rotation{1, 0, 0, 0}; //!< camera-to-world rotation
    Projection projection = Projection::Perspective;
    double fov_y_degrees = 40;    //!< vertical field of view (perspective)
    glm::dvec3 scene_center{0.0}; //!< of the shown mesh's box: with the radius,
    double scene_radius = 1;      //!< what near and far must contain
    UpAxis up_axis = UpAxis::Y;   //!< the standard views and the turntable follow it

    //! The world's up direction: +y or +z.
    glm::dvec3 world_up() const;

    glm::dvec3 eye() const;
    glm::dvec3 forward() const; //!< unit view direction
    glm::dvec3 up() const;
    glm::dvec3 right() const;

    //! \brief Near and far planes that contain the whole scene sphere wherever the eye is;
    //! in perspective near stays positive (at least 1e-4 of the radius) when the eye is
    //! inside the sphere.
    double near_plane() const;
    double far_plane() const;
    //! Height in world units of what the view shows at the target's depth.
    double view_height() const;

    glm::dmat4 view_matrix() const;
    glm::dmat4 projection_matrix(double aspect) const;

    //! Window pixel coordinates (x, y) and depth of a world point.
    glm::dvec3 project(const glm::dvec3& p, int width, int height) const;
    //! The world point at window pixel (x, y) and depth (inverse of project).
    glm::dvec3 unproject(const glm::dvec3& window, int width, int height) const;

    //! \brief Looks at the whole box: the target moves to its centre, the distance makes its
    //! bounding sphere fit the narrower side of the window with a 5 % margin; the
    //! direction is kept. The box also becomes the scene (near and far).
    void frame(const Box3& box, double aspect);
    //! \brief Looks at `part` of the scene (a selection) as frame does, while near and far
    //! still contain the whole `scene`.
    void frame(const Box3& part, const Box3& scene, double aspect);
    //! Looks along a standard view's axis (the distance and target are kept).
    void set_view(StandardView view);

    //! \brief Rotates for a mouse motion from (x0, y0) to (x1, y1) in pixels.
    //! Turntable: 180 degrees per window height. Trackball: Shoemake's arcball on the
    //! sphere inscribed in the window.
    void orbit(OrbitStyle style, double x0, double y0, double x1, double y1, int width, int height);
    //! Moves the target with the mouse: the point under the cursor at the target's depth
    //! follows the cursor.
    void pan(double dx_px, double dy_px, int width, int height);
    //! \brief Zooms by `factor` (< 1 closer) keeping the point under the cursor, at the
    //! target's depth, fixed on screen (zoom to cursor).
    void zoom(double factor, double x_px, double y_px, int width, int height);
};

//! \brief Every point of `positions` (3 n coordinates) in window pixels and depth, as
//! Camera::project gives them, computed on the threads.
std::vector<ScreenPoint> project_points(const Camera& camera, std::span<const float> positions,
                                        int width, int height);

//! The camera as JSON (target, distance, rotation as w x y z, projection, fov, radius).
std::string to_json(const Camera& camera);
//! \brief Reads a camera written by to_json; `name` names the source in messages.
//! \throw InvalidInputError naming the field at fault.
//! \brief With `scene`, a view that gives no scene centre or radius (written by hand, or by
//! another program) gets them from that box, so that near and far contain the mesh; one
//! without a target or a distance gets those of the box framed (Camera::frame, aspect 1)
//! with the view's own rotation, projection and field of view.
Camera camera_from_json(const std::string& text, const std::string& name,
                        const Box3* scene = nullptr);

} // namespace meshfair::app
