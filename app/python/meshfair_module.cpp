// SPDX-License-Identifier: MIT
// Copyright 2026 the MeshFair authors.
//
// The `meshfair` Python module: MeshFair's readers, writers and smoothing on NumPy arrays,
// through the same core calls as meshfair-cli (check_recipe, LocalityRun, run), so that
// smooth() gives the CLI's positions bit for bit. Documented in docs/python.md.
#include <pybind11/numpy.h>
#include <pybind11/pybind11.h>
#include <pybind11/stl.h>

#include <algorithm>
#include <cmath>
#include <memory>
#include <optional>
#include <string>
#include <utility>
#include <vector>

#include "core/errors.h"
#include "core/io/io.h"
#include "core/mesh/mesh.h"
#include "core/recipe/energy_terms.h"
#include "core/recipe/locality_run.h"
#include "core/recipe/recipe.h"
#include "core/recipe/recipe_json.h"
#include "core/recipe/session.h"
#include "core/solver/solver.h"
#include "core/topology/vertex_order.h"

namespace py = pybind11;
using namespace meshfair;

namespace {

using Positions = py::array_t<double, py::array::c_style | py::array::forcecast>;
using Indices = py::array_t<std::int64_t, py::array::c_style | py::array::forcecast>;

// Python's errors for the core's: bad input is a ValueError, a failed write an OSError, a
// solver refusal a RuntimeError; each keeps the core's message (file, line, element).
void register_errors(py::module_& m)
{
    static py::exception<InvalidInputError> input_error(m, "InputError", PyExc_ValueError);
    static py::exception<IOError> io_error(m, "WriteError", PyExc_OSError);
    static py::exception<SolverError> solver_error(m, "SolverError", PyExc_RuntimeError);
    py::register_exception_translator([](std::exception_ptr p) {
        try
        {
            if (p)
                std::rethrow_exception(p);
        }
        catch (const InvalidInputError& e)
        {
            input_error(e.what());
        }
        catch (const IOError& e)
        {
            io_error(e.what());
        }
        catch (const SolverError& e)
        {
            solver_error(e.what());
        }
    });
}

// V as an (n, 3) array of finite numbers, F as an (m, k) integer array or a pair
// (offsets of m + 1, indices): the mesh they make, validated as a file's would be.
Mesh mesh_from(const Positions& vertices, const py::object& faces)
{
    if (vertices.ndim() != 2 || vertices.shape(1) != 3)
        throw InvalidInputError("V must be an (n, 3) array of vertex positions");
    Mesh mesh;
    mesh.positions.assign(vertices.data(), vertices.data() + vertices.size());
    std::vector<std::int64_t> offsets, indices;
    if (py::isinstance<py::tuple>(faces) || py::isinstance<py::list>(faces))
    {
        const auto pair = faces.cast<py::sequence>();
        if (pair.size() != 2)
            throw InvalidInputError("F must be an (m, k) array or a pair (offsets, indices)");
        const auto o = pair[0].cast<Indices>();
        const auto i = pair[1].cast<Indices>();
        if (o.ndim() != 1 || i.ndim() != 1 || o.size() < 1)
            throw InvalidInputError(
                "F's offsets and indices must be one-dimensional, the "
                "offsets m + 1 long");
        offsets.assign(o.data(), o.data() + o.size());
        indices.assign(i.data(), i.data() + i.size());
    }
    else
    {
        const auto f = faces.cast<Indices>();
        if (f.ndim() != 2)
            throw InvalidInputError("F must be an (m, k) array or a pair (offsets, indices)");
        indices.assign(f.data(), f.data() + f.size());
        for (py::ssize_t k = 0; k <= f.shape(0); ++k)
            offsets.push_back(k * f.shape(1));
    }
    if (offsets.front() != 0 || offsets.back() != static_cast<std::int64_t>(indices.size()))
        throw InvalidInputError("F's offsets must start at 0 and end at the number of indices");
    mesh.face_offsets.clear();
    for (size_t k = 0; k < offsets.size(); ++k)
    {
        if (k > 0 && offsets[k] < offsets[k - 1])
            throw InvalidInputError("F's offsets must not decrease (offset " + std::to_string(k) +
                                    ")");
        if (offsets[k] > kMaxElements)
            throw InvalidInputError("F has more corners than MeshFair supports");
        mesh.face_offsets.push_back(static_cast<Index>(offsets[k]));
    }
    for (size_t k = 0; k < indices.size(); ++k)
    {
        if (indices[k] < 0 || indices[k] >= static_cast<std::int64_t>(vertices.shape(0)))
            throw InvalidInputError("F's index " + std::to_string(k) + " is " +
                                    std::to_string(indices[k]) + ", not a vertex of V (0 to " +
                                    std::to_string(vertices.shape(0) - 1) + ")");
        mesh.face_vertices.push_back(static_cast<Index>(indices[k]));
    }
    validate_mesh(mesh);
    return mesh;
}

Positions positions_of(const std::vector<Scalar>& x)
{
    Positions out({static_cast<py::ssize_t>(x.size() / 3), py::ssize_t{3}});
    std::copy(x.begin(), x.end(), out.mutable_data());
    return out;
}

// F as an (m, k) array when every face has k corners, else (offsets, indices).
py::object faces_of(const Mesh& mesh)
{
    const Index m = mesh.face_count();
    const Index k = m > 0 ? mesh.face_size(0) : 3;
    const bool uniform = std::all_of(mesh.face_offsets.begin(), mesh.face_offsets.end(),
                                     [&, f = Index{0}](Index o) mutable { return o == k * f++; });
    if (uniform)
    {
        Indices f({static_cast<py::ssize_t>(m), static_cast<py::ssize_t>(k)});
        std::copy(mesh.face_vertices.begin(), mesh.face_vertices.end(), f.mutable_data());
        return py::object(std::move(f));
    }
    Indices offsets(static_cast<py::ssize_t>(mesh.face_offsets.size()));
    std::copy(mesh.face_offsets.begin(), mesh.face_offsets.end(), offsets.mutable_data());
    Indices indices(static_cast<py::ssize_t>(mesh.face_vertices.size()));
    std::copy(mesh.face_vertices.begin(), mesh.face_vertices.end(), indices.mutable_data());
    return py::make_tuple(offsets, indices);
}

// A recipe from a dict (as json.loads gives it) or JSON text, checked against the mesh.
Recipe recipe_from(const py::object& recipe, const Mesh& mesh)
{
    std::string text;
    if (recipe.is_none())
        text = "{}";
    else if (py::isinstance<py::str>(recipe))
        text = recipe.cast<std::string>();
    else
        text = py::module_::import("json").attr("dumps")(recipe).cast<std::string>();
    Recipe r = parse_recipe(text, "recipe");
    check_recipe(r, mesh);
    return r;
}

//! The run's notes (how open components' volumes are kept, ...) as meshfair.SolverNote
//! warnings, as meshfair-cli puts them in its report.
void warn_solver_notes(const std::vector<std::string>& notes)
{
    if (notes.empty())
        return;
    const py::object warn = py::module_::import("warnings").attr("warn");
    const py::object category = py::module_::import("meshfair").attr("SolverNote");
    for (const std::string& note : notes)
        warn(note, category, 2);
}

py::dict energies_of(const TermEnergies& e)
{
    py::dict d;
    for (const EnergyTermInfo& t : energy_terms())
        d[py::str(std::string(t.key))] = e.*(t.energy);
    d["total"] = e.total();
    return d;
}

//! A smoothing run kept between calls, as the editor keeps one: precomputed once, stepped
//! as often as asked, in the file's numbering for the caller.
class PySession
{
public:
    PySession(const Positions& vertices, const py::object& faces, const py::object& recipe)
    {
        Mesh mesh = mesh_from(vertices, faces);
        const Recipe r = recipe_from(recipe, mesh);
        {
            py::gil_scoped_release unlocked;
            run_ = std::make_unique<LocalityRun>(std::move(mesh), r);
        }
        warn_solver_notes(run_->session().notes());
    }
    std::vector<std::string> notes() const { return run_->session().notes(); }
    void step(int steps)
    {
        if (steps < 0)
            throw InvalidInputError("step: the number of steps must be >= 0");
        py::gil_scoped_release unlocked;
        for (int k = 0; k < steps; ++k)
            run_->step();
    }
    py::dict energy() const { return energies_of(run_->energy()); }
    //! The recipe's run on the kept positions, as meshfair-cli smooth runs it: with the
    //! direct method, to the minimizer (reusing the factorization after new targets).
    py::dict solve()
    {
        SmoothResult result;
        {
            py::gil_scoped_release unlocked;
            result = run(run_->session());
        }
        py::dict d;
        d["iterations"] = result.iterations;
        d["stopped_by_tolerance"] = result.stopped_by_tolerance;
        d["relative_gradient"] = result.gradients;
        d["energy"] = energies_of(result.energies.back());
        return d;
    }
    Positions positions() const
    {
        std::vector<Scalar> x(run_->session().positions().size());
        positions_to_file_order(run_->session().positions(), run_->order(), x);
        return positions_of(x);
    }
    //! New targets of the hard vertices (recipe order): the kept positions move there, as
    //! the editor's dragged pins move them.
    void set_hard_targets(const Positions& targets)
    {
        const std::span<const Scalar> t(targets.data(), static_cast<size_t>(targets.size()));
        if (!std::all_of(t.begin(), t.end(), [](Scalar v) { return std::isfinite(v); }))
            throw InvalidInputError("set_hard_targets: every target coordinate must be finite");
        // (The kept positions' pins move; the next solve follows the minimizer from the
        // one it had, without a solve where the pins moved together: Session::follow_pins.)
        run_->session().move_pins(t);
    }

private:
    std::unique_ptr<LocalityRun> run_;
};

} // namespace

PYBIND11_MODULE(meshfair, m)
{
    m.doc() =
        "MeshFair: polygon mesh smoothing (Taubin 2012 energies, generalized Jacobi "
        "solver) on NumPy arrays.";
    register_errors(m);

    // What a reader skipped or changed (the notes meshfair-cli prints) reaches Python as
    // warnings of this category, never silently.
    m.attr("ReadNote") = py::reinterpret_steal<py::object>(
        PyErr_NewException("meshfair.ReadNote", PyExc_UserWarning, nullptr));
    // What a run does besides the recipe's letter (the notes of meshfair-cli's report: how
    // open components' volumes are kept, a falloff with nothing to fade from).
    m.attr("SolverNote") = py::reinterpret_steal<py::object>(
        PyErr_NewException("meshfair.SolverNote", PyExc_UserWarning, nullptr));
    m.def(
        "read",
        [](const std::string& path) {
            io::ReadReport report;
            io::MeshAttributes attributes;
            const Mesh mesh = io::read_mesh(path, &report, &attributes);
            const py::object warn = py::module_::import("warnings").attr("warn");
            const py::object category = py::module_::import("meshfair").attr("ReadNote");
            for (const std::string& note : report.notes)
                warn("'" + path + "': " + note, category, 2);
            // (V, F) holds none of the attributes: say which, so none is lost unnoticed
            // (meshfair-cli smooth keeps them).
            for (const std::string& kind : io::describe_attributes(attributes))
                warn("'" + path + "': not returned (read gives positions and faces only; " +
                         "meshfair-cli keeps it): " + kind,
                     category, 2);
            return py::make_tuple(positions_of(mesh.positions), faces_of(mesh));
        },
        py::arg("path"),
        "Reads an OBJ, OFF, PLY or STL file (by its extension): (V, F), V an (n, 3) float64 "
        "array, F an (m, k) int64 array when every face has k corners, else a pair (offsets, "
        "indices). What the reader skipped or changed, and every attribute of the file (texture "
        "coordinates, normals, colours, ...) that (V, F) cannot hold, is warned of as "
        "meshfair.ReadNote.");
    m.def(
        "write",
        [](const std::string& path, const Positions& vertices, const py::object& faces) {
            io::write_mesh(mesh_from(vertices, faces), path);
        },
        py::arg("path"), py::arg("V"), py::arg("F"),
        "Writes (V, F) to path, its format from the extension, atomically (an existing file "
        "is kept whole if the write fails).");
    m.def(
        "smooth",
        [](const Positions& vertices, const py::object& faces, const py::object& recipe) {
            Mesh mesh = mesh_from(vertices, faces);
            const Recipe r = recipe_from(recipe, mesh);
            LocalityRun::Released solved;
            std::vector<std::string> notes;
            {
                py::gil_scoped_release unlocked;
                LocalityRun run(std::move(mesh), r);
                meshfair::run(run.session());
                notes = run.session().notes();
                solved = std::move(run).release();
            }
            warn_solver_notes(notes);
            return positions_of(file_order_mesh(std::move(solved)).positions);
        },
        py::arg("V"), py::arg("F"), py::arg("recipe") = py::none(),
        "Smooths (V, F) with a recipe (a dict or JSON text, docs/recipe.md; None: the "
        "defaults) as meshfair-cli smooth does, and returns the new (n, 3) positions. What "
        "the run does besides the recipe's letter (the report's notes: how open components' "
        "volumes are kept, ...) is warned of as meshfair.SolverNote.");

    py::class_<PySession>(m, "Session",
                          "A precomputed smoothing run on (V, F) with a recipe, stepped on "
                          "demand.")
        .def(py::init<const Positions&, const py::object&, const py::object&>(), py::arg("V"),
             py::arg("F"), py::arg("recipe") = py::none())
        .def("step", &PySession::step, py::arg("steps") = 1,
             "Runs steps steps of the recipe's method on the kept positions (with \"method\": "
             "\"direct\", each solves for the minimizer from where it starts).")
        .def("solve", &PySession::solve,
             "Runs the recipe on the kept positions as meshfair-cli smooth does: its "
             "iterations, stopped by its tolerance; with \"method\": \"direct\", to the "
             "minimizer, the factorization kept from the session's creation (new targets "
             "only change the right-hand side). Returns the iterations, the relative gradient "
             "after each (direct) and the final energy.")
        .def("energy", &PySession::energy,
             "The energy of the kept positions, by term, and its total.")
        .def_property_readonly("positions", &PySession::positions,
                               "The kept positions, an (n, 3) array (a copy).")
        .def_property_readonly("notes", &PySession::notes,
                               "What the run does besides the recipe's letter (also warned of "
                               "as meshfair.SolverNote when the session is made).")
        .def("set_hard_targets", &PySession::set_hard_targets, py::arg("targets"),
             "New targets of the recipe's hard vertices, one row each, in the recipe's order.");
}
