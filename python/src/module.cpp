// The Python module `sweep` (its compiled part, sweep._sweep): the public C++ API of
// <sweep/sweep.hpp> with numpy arrays that are views of the document's memory (arrays.hpp).
// sweep/__init__.py re-exports it; sweep/_sweep.pyi types it for editors.
#include "arrays.hpp"

#include <pybind11/stl.h>
#include <pybind11/stl/filesystem.h>
#include <sweep/sweep.hpp>

#include <string>

namespace sweep_python {
namespace {

using Array = py::array_t<double, py::array::c_style | py::array::forcecast>;

std::span<const double> span_of(const Array& values) {
  if (values.ndim() != 1) throw py::value_error("expected a one-dimensional array of parameters");
  return {values.data(), static_cast<std::size_t>(values.size())};
}

py::array_t<float> floats(std::span<const float> values, py::ssize_t width, const py::capsule& base) {
  const py::ssize_t rows = static_cast<py::ssize_t>(values.size()) / width;
  return view<float>(values.data(), {rows, width}, c_strides<float>({rows, width}), base);
}

py::array_t<std::uint32_t> triangles(const sweep::SurfaceMesh& m) {
  const py::ssize_t n = static_cast<py::ssize_t>(m.triangle_count());
  return view<std::uint32_t>(m.indices.data(), {n, 3}, c_strides<std::uint32_t>({n, 3}), keep_alive(m.owner));
}

/// (N, 4, 3) float64 over frames: V, T, N, B of each sample.
py::array_t<double> frame_array(std::span<const sweep::Frame> frames, const py::capsule& base) {
  const py::ssize_t n = static_cast<py::ssize_t>(frames.size());
  return view<double>(reinterpret_cast<const double*>(frames.data()), {n, 4, 3}, c_strides<double>({n, 4, 3}), base);
}

/// (N, 3) float64 of the samples' positions: a strided view of the frames.
py::array_t<double> position_array(std::span<const sweep::Frame> frames, const py::capsule& base) {
  const py::ssize_t n = static_cast<py::ssize_t>(frames.size());
  return view<double>(reinterpret_cast<const double*>(frames.data()), {n, 3},
                      {static_cast<py::ssize_t>(sizeof(sweep::Frame)), sizeof(double)}, base);
}

void register_errors(py::module_& m) {
  static py::exception<sweep::Error> swp_error(m, "SwpError", PyExc_ValueError);
  py::register_exception_translator([](std::exception_ptr thrown) {
    try {
      if (thrown) std::rethrow_exception(thrown);
    } catch (const sweep::Error& e) {
      py::object error = py::handle(swp_error.ptr())(e.what());
      error.attr("file") = e.file();
      error.attr("line") = e.line();
      error.attr("column") = e.column();
      PyErr_SetObject(swp_error.ptr(), error.ptr());
    }
  });
}

void bind_views(py::module_& m) {
  py::class_<sweep::SurfaceMesh>(m, "Surface", "A surface's triangle mesh; its arrays are read-only views")
      .def_readonly("name", &sweep::SurfaceMesh::name)
      .def_readonly("kind", &sweep::SurfaceMesh::kind)
      .def_property_readonly("positions",
                             [](const sweep::SurfaceMesh& s) { return floats(s.positions, 3, keep_alive(s.owner)); })
      .def_property_readonly("normals",
                             [](const sweep::SurfaceMesh& s) { return floats(s.normals, 3, keep_alive(s.owner)); })
      .def_property_readonly("uvs", [](const sweep::SurfaceMesh& s) { return floats(s.uvs, 2, keep_alive(s.owner)); })
      .def_property_readonly("indices", triangles)
      .def_property_readonly("vertex_count", &sweep::SurfaceMesh::vertex_count)
      .def_property_readonly("triangle_count", &sweep::SurfaceMesh::triangle_count)
      .def("__repr__", [](const sweep::SurfaceMesh& s) {
        return "<sweep.Surface " + s.name + " (" + s.kind + "): " + std::to_string(s.vertex_count()) + " vertices, " +
               std::to_string(s.triangle_count()) + " triangles>";
      });
  py::class_<sweep::CurveView>(m, "Curve", "A curve's samples and frames; its arrays are read-only views")
      .def_readonly("name", &sweep::CurveView::name)
      .def_readonly("kind", &sweep::CurveView::kind)
      .def_readonly("planar", &sweep::CurveView::planar)
      .def_readonly("closed", &sweep::CurveView::closed)
      .def_property_readonly("frames",
                             [](const sweep::CurveView& c) { return frame_array(c.frames, keep_alive(c.owner)); })
      .def_property_readonly("positions",
                             [](const sweep::CurveView& c) { return position_array(c.frames, keep_alive(c.owner)); })
      .def_property_readonly("parameters",
                             [](const sweep::CurveView& c) {
                               const py::ssize_t n = static_cast<py::ssize_t>(c.parameters.size());
                               return view<double>(c.parameters.data(), {n}, {sizeof(double)}, keep_alive(c.owner));
                             })
      .def("__repr__", [](const sweep::CurveView& c) {
        return "<sweep.Curve " + c.name + " (" + c.kind + "): " + std::to_string(c.sample_count()) + " samples>";
      });
  py::class_<sweep::ObjectInfo>(m, "ObjectInfo")
      .def_readonly("name", &sweep::ObjectInfo::name)
      .def_readonly("kind", &sweep::ObjectInfo::kind)
      .def_readonly("category", &sweep::ObjectInfo::category)
      .def_readonly("points", &sweep::ObjectInfo::points)
      .def("__repr__", [](const sweep::ObjectInfo& o) { return "<sweep.ObjectInfo " + o.name + " (" + o.kind + ")>"; });
  py::class_<sweep::PrintFinding>(m, "PrintFinding", "One finding of Document.check_print")
      .def_readonly("check", &sweep::PrintFinding::check)
      .def_readonly("object", &sweep::PrintFinding::object)
      .def_readonly("other", &sweep::PrintFinding::other)
      .def_readonly("line", &sweep::PrintFinding::line)
      .def_readonly("message", &sweep::PrintFinding::message)
      .def_readonly("where", &sweep::PrintFinding::where)
      .def_readonly("fails", &sweep::PrintFinding::fails)
      .def("__repr__", [](const sweep::PrintFinding& f) { return "<sweep.PrintFinding " + f.message + ">"; });
}

py::array_t<std::uint8_t> image_array(sweep::Image image) {
  const py::ssize_t h = image.height;
  const py::ssize_t w = image.width;
  const std::uint8_t* data = image.rgba.data();
  const py::capsule base = owning(std::move(image.rgba));
  return view<std::uint8_t>(data, {h, w, 4}, c_strides<std::uint8_t>({h, w, 4}), base);
}

sweep::Image image_of(const py::array_t<std::uint8_t, py::array::c_style | py::array::forcecast>& rgba) {
  if (rgba.ndim() != 3 || rgba.shape(2) != 4) throw py::value_error("expected an (height, width, 4) uint8 array");
  return {static_cast<int>(rgba.shape(1)), static_cast<int>(rgba.shape(0)),
          std::vector<std::uint8_t>(rgba.data(), rgba.data() + rgba.size())};
}

sweep::EvaluationOptions evaluation(const std::string& frames, const std::string& seam, double tolerance, bool uvs) {
  return {frames, seam, tolerance, uvs};
}

void bind_document(py::module_& m) {
  py::class_<sweep::Document>(m, "Document", "An SWP document, evaluated (load() or parse() makes one)")
      .def("objects", &sweep::Document::objects)
      .def("surfaces", &sweep::Document::surfaces)
      .def("curves", &sweep::Document::curves)
      .def("surface", &sweep::Document::surface, py::arg("name"))
      .def("curve", &sweep::Document::curve, py::arg("name"))
      .def("curve_range", &sweep::Document::curve_range, py::arg("name"))
      .def(
          "evaluate_curve",
          [](const sweep::Document& d, const std::string& name, const Array& t) {
            const sweep::CurveFrames f = [&] {
              py::gil_scoped_release free;
              return d.evaluate_curve(name, span_of(t));
            }();
            const py::capsule base = keep_alive(f.owner);
            return py::make_tuple(position_array(f.frames, base), frame_array(f.frames, base));
          },
          py::arg("name"), py::arg("parameters"))
      .def(
          "curve_points",
          [](const sweep::Document& d, const std::string& name, const Array& t) {
            std::vector<double> points = [&] {
              py::gil_scoped_release free;
              return d.curve_points(name, span_of(t));
            }();
            const py::ssize_t n = static_cast<py::ssize_t>(points.size() / 3);
            const double* data = points.data();
            return view<double>(data, {n, 3}, c_strides<double>({n, 3}), owning(std::move(points)));
          },
          py::arg("name"), py::arg("parameters"))
      .def("point", &sweep::Document::point, py::arg("object"), py::arg("index"))
      .def(
          "set_point",
          [](sweep::Document& d, const std::string& object, int index, const std::vector<double>& xyz) {
            if (xyz.size() != 2 && xyz.size() != 3) throw py::value_error("a point is (x, y) or (x, y, z)");
            d.move_point(object, index, {xyz[0], xyz[1], xyz.size() == 3 ? xyz[2] : 0.0});
          },
          py::arg("object"), py::arg("index"), py::arg("position"))
      .def("set_field", &sweep::Document::set_field, py::arg("object"), py::arg("field"), py::arg("value"))
      .def("undo", &sweep::Document::undo)
      .def("redo", &sweep::Document::redo)
      .def_property_readonly("can_undo", &sweep::Document::can_undo)
      .def_property_readonly("can_redo", &sweep::Document::can_redo)
      .def_property_readonly("modified", &sweep::Document::modified)
      .def_property_readonly("file", &sweep::Document::file)
      .def("text", &sweep::Document::text)
      .def("save", &sweep::Document::save, py::arg("path"))
      .def(
          "export",
          [](const sweep::Document& d, const std::filesystem::path& prefix, const std::string& format, double height,
             bool merge, double min_wall) {
            const sweep::ExportFormat f = format == "obj"   ? sweep::ExportFormat::Obj
                                          : format == "stl" ? sweep::ExportFormat::Stl
                                          : format == "glb" ? sweep::ExportFormat::Glb
                                          : format == "3mf"
                                              ? sweep::ExportFormat::ThreeMf
                                              : throw py::value_error("format must be obj, stl, glb or 3mf");
            return d.export_surfaces(prefix, f, {height, merge, min_wall});
          },
          py::arg("prefix"), py::arg("format") = "obj", py::arg("height") = 0.0, py::arg("merge") = false,
          py::arg("min_wall") = 0.8)
      .def(
          "check_print",
          [](const sweep::Document& d, double height, double min_wall) {
            return d.check_print({height, false, min_wall});
          },
          py::arg("height") = 0.0, py::arg("min_wall") = 0.8)
      .def(
          "render",
          [](const sweep::Document& d, int width, int height, const std::string& mode, const std::string& color,
             double yaw, double pitch) {
            sweep::Image image = [&] {
              py::gil_scoped_release free;
              return d.render(width, height, {mode, color, yaw, pitch});
            }();
            return image_array(std::move(image));
          },
          py::arg("width") = 640, py::arg("height") = 480, py::arg("mode") = "smooth", py::arg("color") = "material",
          py::arg("yaw") = 30.0, py::arg("pitch") = 20.0)
      .def("_repr_png_", [](const sweep::Document& d) { return py::bytes(d.render(640, 480).png()); })
      .def("__repr__", [](const sweep::Document& d) {
        return "<sweep.Document " + (d.file().empty() ? std::string("(from text)") : d.file().string()) + ": " +
               std::to_string(d.objects().size()) + " objects>";
      });
}

void bind_functions(py::module_& m) {
  m.def(
      "load",
      [](const std::filesystem::path& path, const std::string& frames, const std::string& seam, double tolerance,
         bool uvs) { return sweep::Document::load(path, evaluation(frames, seam, tolerance, uvs)); },
      py::arg("path"), py::arg("frames") = "rmf", py::arg("seam") = "full", py::arg("tolerance") = 0.0,
      py::arg("uvs") = false);
  m.def(
      "parse",
      [](const std::string& text, const std::string& name, const std::string& frames, const std::string& seam,
         double tolerance,
         bool uvs) { return sweep::Document::parse(text, name, evaluation(frames, seam, tolerance, uvs)); },
      py::arg("text"), py::arg("name") = "<string>", py::arg("frames") = "rmf", py::arg("seam") = "full",
      py::arg("tolerance") = 0.0, py::arg("uvs") = false);
  m.def(
      "compare_images",
      [](const py::array_t<std::uint8_t>& actual, const py::array_t<std::uint8_t>& reference, double threshold,
         std::size_t max_diff_pixels) {
        const sweep::Comparison c =
            sweep::compare_images(image_of(actual), image_of(reference), {threshold, max_diff_pixels});
        py::dict out;
        out["matches"] = c.matches;
        out["same_size"] = c.same_size;
        out["differing_pixels"] = c.differing_pixels;
        out["changed_pixels"] = c.changed_pixels;
        out["max_distance"] = c.max_distance;
        out["summary"] = c.summary;
        return out;
      },
      py::arg("actual"), py::arg("reference"), py::arg("threshold") = 0.1, py::arg("max_diff_pixels") = 8);
  m.def("save_png", [](const py::array_t<std::uint8_t>& rgba, const std::filesystem::path& path) {
    image_of(rgba).save_png(path);
  });
  py::class_<sweep::SnapshotResult>(m, "SnapshotResult")
      .def_readonly("status", &sweep::SnapshotResult::status)
      .def_readonly("passed", &sweep::SnapshotResult::passed)
      .def_readonly("message", &sweep::SnapshotResult::message)
      .def_readonly("objects", &sweep::SnapshotResult::objects)
      .def_readonly("changed_objects", &sweep::SnapshotResult::changed_objects)
      .def_readonly("reference", &sweep::SnapshotResult::reference);
  m.def(
      "check_snapshot",
      [](const sweep::Document& d, const std::filesystem::path& folder, const std::string& name,
         const std::string& mode, int width, int height, double threshold, std::size_t max_diff_pixels, bool update) {
        py::gil_scoped_release free;
        return sweep::check_snapshot(d, folder, name, {mode, width, height, threshold, max_diff_pixels, update});
      },
      py::arg("document"), py::arg("folder"), py::arg("name"), py::arg("mode") = "smooth", py::arg("width") = 320,
      py::arg("height") = 240, py::arg("threshold") = 0.1, py::arg("max_diff_pixels") = 8, py::arg("update") = false);
}

}  // namespace
}  // namespace sweep_python

PYBIND11_MODULE(_sweep, m) {
  m.doc() = "Sweep: spline curves and swept surfaces from SWP files (the compiled part of the sweep package)";
  m.attr("__version__") = SWEEP_VERSION_STRING;
  sweep_python::register_errors(m);
  sweep_python::bind_views(m);
  sweep_python::bind_document(m);
  sweep_python::bind_functions(m);
}
