#include "app/writers.hpp"

#include <cstdint>
#include <cstring>
#include <functional>
#include <sstream>
#include <stdexcept>
#include <utility>

#include "app/file.hpp"
#include "app/formatted.hpp"

namespace num::app {

using sph::Float;
using sph::Size;

namespace {

/// How VTK stores one field: Float64 with 1 or 3 components, or Int32.
struct FieldLayout {
    int components;
    const char* type;
    std::uint64_t bytesPerParticle;
};
FieldLayout layoutOf(const OutputField& f) {
    if (f.type == OutputField::Type::VECTOR) return {3, "Float64", 24};
    if (f.type == OutputField::Type::FLOAT) return {1, "Float64", 8};
    return {1, "Int32", 4};
}

/// The bytes of one field, as layoutOf(f) says.
template <int Dim>
std::vector<char> fieldBytes(const sph::Storage<Dim>& s, const OutputField& f) {
    std::vector<char> bytes;
    auto append = [&](const auto& v) {
        const char* p = reinterpret_cast<const char*>(&v);
        bytes.insert(bytes.end(), p, p + sizeof v);
    };
    const Size n = s.size();
    bytes.reserve(n * layoutOf(f).bytesPerParticle);
    if (f.type == OutputField::Type::VECTOR) {
        const auto v = f.derivative ? s.template getDt<sph::Vector<Dim>>(f.id)
                                    : s.template getValue<sph::Vector<Dim>>(f.id);
        for (Size i = 0; i < n; ++i)
            for (int k = 0; k < 3; ++k) append(double(k < Dim ? v[i][k] : 0.0));
    } else if (f.type == OutputField::Type::FLOAT) {
        for (double x : s.template getValue<Float>(f.id)) append(x);
    } else {
        for (int x : s.template getValue<int>(f.id)) append(std::int32_t(x));
    }
    return bytes;
}

/// The cells' indices: one vertex per particle (connectivity i, offsets i + 1), from `first`.
std::vector<char> vertexIndices(std::uint64_t n, std::int64_t first) {
    std::vector<char> bytes(n * 8);
    for (std::uint64_t i = 0; i < n; ++i) {
        const std::int64_t v = std::int64_t(i) + first;
        std::memcpy(&bytes[i * 8], &v, 8);
    }
    return bytes;
}

/// A VTU file's arrays in its appended block, each as its byte count (UInt64) and its bytes:
/// their sizes are known in advance, so the XML is written first and each array is made and
/// written in turn (one array in memory at a time, not all of them).
class AppendedArrays {
  public:
    /// Declares an array in the XML; `make` gives its bytes when the block is written.
    void add(const std::string& name, const std::string& type, int components, std::uint64_t bytes,
             std::function<std::vector<char>()> make) {
        xml << "        <DataArray type=\"" << type << "\" Name=\"" << name
            << "\" NumberOfComponents=\"" << components << "\" format=\"appended\" offset=\""
            << offset_ << "\"/>\n";
        offset_ += sizeof(std::uint64_t) + bytes;
        arrays_.emplace_back(bytes, std::move(make));
    }
    /// Writes the XML, then each array.
    void write(OutFile& out) const {
        out.write(xml.str());
        for (const auto& [size, make] : arrays_) {
            const std::vector<char> bytes = make();
            if (bytes.size() != size)
                throw std::logic_error("writeVtu: an array's size differs from its header's");
            out.write(&size, sizeof size);
            out.write(bytes.data(), bytes.size());
        }
    }
    std::ostringstream xml;

  private:
    std::uint64_t offset_ = 0;
    std::vector<std::pair<std::uint64_t, std::function<std::vector<char>()>>> arrays_;
};

}  // namespace

template <int Dim>
void writeVtu(const std::string& path, const sph::Storage<Dim>& s,
              const std::vector<OutputField>& fields, double time) {
    const std::uint64_t n = s.size();
    AppendedArrays block;
    block.xml << "<?xml version=\"1.0\"?>\n"
              << "<VTKFile type=\"UnstructuredGrid\" version=\"1.0\" byte_order=\"LittleEndian\" "
                 "header_type=\"UInt64\">\n"
              << "  <UnstructuredGrid>\n"
              << "    <FieldData>\n"
              << "      <DataArray type=\"Float64\" Name=\"TimeValue\" NumberOfTuples=\"1\" "
                 "format=\"ascii\">"
              << formatted("%.17g", time) << "</DataArray>\n"
              << "    </FieldData>\n"
              << "    <Piece NumberOfPoints=\"" << n << "\" NumberOfCells=\"" << n << "\">\n"
              << "      <PointData Scalars=\"temperature\" Vectors=\"velocity\">\n";
    for (const OutputField& f : fields) {
        const FieldLayout l = layoutOf(f);
        block.add(f.name, l.type, l.components, n * l.bytesPerParticle,
                  [&s, &f] { return fieldBytes(s, f); });
    }
    block.xml << "      </PointData>\n      <Points>\n";
    const OutputField points{"Points", sph::QuantityId::POSITION, OutputField::Type::VECTOR};
    block.add("Points", "Float64", 3, n * layoutOf(points).bytesPerParticle,
              [&] { return fieldBytes(s, points); });
    block.xml << "      </Points>\n      <Cells>\n";
    block.add("connectivity", "Int64", 1, n * 8, [n] { return vertexIndices(n, 0); });
    block.add("offsets", "Int64", 1, n * 8, [n] { return vertexIndices(n, 1); });
    block.add("types", "UInt8", 1, n, [n] { return std::vector<char>(n, char(1)); });  // VTK_VERTEX
    block.xml << "      </Cells>\n    </Piece>\n  </UnstructuredGrid>\n"
              << "  <AppendedData encoding=\"raw\">\n   _";
    OutFile out(path);
    block.write(out);
    out.write("\n  </AppendedData>\n</VTKFile>\n");
    out.close();
}

template <int Dim>
void writeCsv(const std::string& path, const sph::Storage<Dim>& s,
              const std::vector<OutputField>& fields) {
    std::string text;
    const char* axes = "xyz";
    for (int k = 0; k < Dim; ++k) {
        if (k) text += ',';
        text += axes[k];
    }
    for (const OutputField& f : fields) {
        if (f.type == OutputField::Type::VECTOR)
            for (int k = 0; k < Dim; ++k) {
                text += ',';
                text += f.name == "velocity" ? std::string("v") : f.name + "_";
                text += axes[k];
            }
        else {
            text += ',';
            text += f.name;
        }
    }
    text += "\n";
    const bool haveKind = s.has(sph::QuantityId::KIND);
    const auto x = s.template getValue<sph::Vector<Dim>>(sph::QuantityId::POSITION);
    OutFile out(path);
    for (Size i = 0; i < s.size(); ++i) {
        if (haveKind && s.template getValue<int>(sph::QuantityId::KIND)[i] != 0) continue;
        for (int k = 0; k < Dim; ++k) text += formatted(k ? ",%.10g" : "%.10g", x[i][k]);
        for (const OutputField& f : fields) {
            if (f.type == OutputField::Type::VECTOR) {
                const auto v = f.derivative ? s.template getDt<sph::Vector<Dim>>(f.id)[i]
                                            : s.template getValue<sph::Vector<Dim>>(f.id)[i];
                for (int k = 0; k < Dim; ++k) text += formatted(",%.10g", v[k]);
            } else if (f.type == OutputField::Type::FLOAT) {
                text += formatted(",%.10g", s.template getValue<Float>(f.id)[i]);
            } else {
                text += ',';
                text += std::to_string(s.template getValue<int>(f.id)[i]);
            }
        }
        text += "\n";
        if (text.size() > (1 << 20)) out.write(text), text.clear();
    }
    out.write(text);
    out.close();
}

void PvdSeries::truncateAfter(double time) {
    while (!entries_.empty() && entries_.back().first > time) entries_.pop_back();
}

void PvdSeries::write(const std::string& path) const {
    std::ostringstream xml;
    xml << "<?xml version=\"1.0\"?>\n"
        << "<VTKFile type=\"Collection\" version=\"0.1\" byte_order=\"LittleEndian\">\n"
        << "  <Collection>\n";
    for (const auto& [t, file] : entries_)
        xml << "    <DataSet timestep=\"" << formatted("%.17g", t)
            << "\" group=\"\" part=\"0\" file=\"" << file << "\"/>\n";
    xml << "  </Collection>\n</VTKFile>\n";
    writeFileAtomically(path, xml.str());
}

template void writeVtu<2>(const std::string&, const sph::Storage<2>&,
                          const std::vector<OutputField>&, double);
template void writeVtu<3>(const std::string&, const sph::Storage<3>&,
                          const std::vector<OutputField>&, double);
template void writeCsv<2>(const std::string&, const sph::Storage<2>&,
                          const std::vector<OutputField>&);
template void writeCsv<3>(const std::string&, const sph::Storage<3>&,
                          const std::vector<OutputField>&);

}  // namespace num::app

namespace num::app {

namespace {

/// "[x, y, z]" with every digit.
std::string pythonList(const double (&a)[3]) {
    return "[" + formatted("%.17g", a[0]) + ", " + formatted("%.17g", a[1]) + ", " +
           formatted("%.17g", a[2]) + "]";
}

/// How to run the script, and the run's figures it uses.
std::string paraviewHeader(const std::string& path, const ParaviewView& v) {
    const std::string name = path.substr(path.rfind('/') + 1);
    std::ostringstream py;
    py << "# Opens this run in ParaView coloured by temperature, fluid and bodies drawn as "
          "spheres\n"
          "# of the particle spacing (walls hidden). Written by the app next to its series.\n"
          "#   paraview --script="
       << name
       << "        the ParaView window, ready to play\n"
          "#   pvpython "
       << name
       << " --screenshot   saves a picture of the last time instead\n"
          "import os\n"
          "import sys\n"
          "from paraview.simple import *\n\n"
          "here = os.path.dirname(os.path.abspath(__file__))\n"
          "series = \""
       << v.pvdName << "\"\ndimension = " << v.dimension
       << "\nspacing = " << formatted("%.17g", v.spacing)
       << "  # m\n"
          "temperature_range = ["
       << formatted("%.17g", v.colorMin) << ", " << formatted("%.17g", v.colorMax) << "]  # C\n\n";
    return py.str();
}

/// Fluid and bodies as spheres coloured by temperature over the pictures' range.
const char* const kParaviewColouring =
    "run = PVDReader(FileName=os.path.join(here, series))\n"
    "view = GetActiveViewOrCreate(\"RenderView\")\n"
    "lut = GetColorTransferFunction(\"temperature\")\n"
    "lut.ApplyPreset(\"Cool to Warm\", True)\n"
    "for kind in (0, 2):  # 0 fluid, 2 bodies (1: walls)\n"
    "    part = Threshold(Input=run, Scalars=[\"POINTS\", \"kind\"])\n"
    "    try:  # ParaView 5.10 and later\n"
    "        part.LowerThreshold, part.UpperThreshold = kind, kind\n"
    "    except AttributeError:\n"
    "        part.ThresholdRange = [kind, kind]\n"
    "    shown = Show(part, view)\n"
    "    shown.SetRepresentationType(\"Point Gaussian\")\n"
    "    shown.GaussianRadius = 0.5 * spacing\n"
    "    shown.ShaderPreset = \"Sphere\"\n"
    "    ColorBy(shown, (\"POINTS\", \"temperature\"))\n"
    "    shown.LookupTable = lut\n"
    "    shown.SetScalarBarVisibility(view, True)\n"
    "# The pictures' colour range, kept while the series plays.\n"
    "lut.AutomaticRescaleRangeMode = \"Never\"\n"
    "lut.RescaleTransferFunction(*temperature_range)\n"
    "GetOpacityTransferFunction(\"temperature\").RescaleTransferFunction(*temperature_range)\n"
    "GetAnimationScene().UpdateAnimationUsingDataTimeSteps()\n"
    "if dimension == 2:\n"
    "    view.InteractionMode = \"2D\"\n";

/// The camera (2D: from +z onto the plane; 3D: from above and aside, the up axis upwards),
/// framing the whole box; then the window or the screenshot.
std::string paraviewCamera(const ParaviewView& v) {
    double camera[3] = {0, 0, 1}, up[3] = {0, 1, 0};
    if (v.dimension == 3) {
        const int a1 = (v.upAxis + 1) % 3, a2 = (v.upAxis + 2) % 3;
        camera[v.upAxis] = 0.9, camera[a1] = 1.0, camera[a2] = -1.4;
        up[0] = up[1] = up[2] = 0, up[v.upAxis] = 1;
    }
    return "view.CameraFocalPoint = [0, 0, 0]\n"
           "view.CameraPosition = " +
           pythonList(camera) + "\nview.CameraViewUp = " + pythonList(up) +
           "\n"
           "# Frame the whole box: the series with its walls is shown while the camera is fitted.\n"
           "box = Show(run, view)\n"
           "view.ResetCamera()\n"
           "Hide(run, view)\n"
           "bounds = run.GetDataInformation().GetBounds()\n"
           "if dimension == 2:  # a 16:9 window holds the box with a little margin\n"
           "    view.CameraParallelScale = 0.55 * max(bounds[3] - bounds[2],\n"
           "                                          (bounds[1] - bounds[0]) * 9 / 16)\n"
           "else:  # the box's edges, and a closer look\n"
           "    Show(Outline(Input=run), view)\n"
           "    GetActiveCamera().Zoom(1.15)\n"
           "bar = GetScalarBar(lut, view)\n"
           "bar.WindowLocation = \"Upper Right Corner\"\n"
           "bar.ScalarBarLength = 0.3\n"
           "if \"--screenshot\" in getattr(sys, \"argv\", []):\n"
           "    GetAnimationScene().GoToLast()\n"
           "    SaveScreenshot(os.path.splitext(os.path.abspath(__file__))[0] + \".png\", view,\n"
           "                   ImageResolution=[1280, 720])\n"
           "else:\n"
           "    Render()\n";
}

}  // namespace

void writeParaviewScript(const std::string& path, const ParaviewView& v) {
    writeFileAtomically(path, paraviewHeader(path, v) + kParaviewColouring + paraviewCamera(v));
}

}  // namespace num::app
