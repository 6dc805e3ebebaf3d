#include "io/outputs.hpp"

#include <unistd.h>

#include <algorithm>
#include <cctype>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <sstream>

#include "io/diagnostics.hpp"
#include "io/file.hpp"
#include "io/formatted.hpp"
#include "io/probe_plot.hpp"

namespace num::io {

using sph::QuantityId;

bool onPath(const std::string& program) {
    const char* path = std::getenv("PATH");
    if (!path) return false;
    std::stringstream dirs(path);
    std::string d;
    while (std::getline(dirs, d, ':'))
        if (!d.empty() && ::access((d + "/" + program).c_str(), X_OK) == 0) return true;
    return false;
}

template <int Dim>
Outputs<Dim>::Outputs(const Scene<Dim>& scene, const SceneSetup<Dim>& setup, std::string directory,
                      const sph::Storage<Dim>& initial, FieldNames names)
    : scene_(scene), setup_(setup), dir_(std::move(directory)), names_(std::move(names)) {
    while (dir_.size() > 1 && dir_.back() == '/') dir_.pop_back();
    // Pictures: the domain (2D with its wall layers), colours over the scene's temperatures.
    render_.min = scene.domainMin, render_.max = scene.domainMax;
    if constexpr (Dim == 2) {
        for (int k = 0; k < Dim; ++k)
            for (int hi = 0; hi < 2; ++hi)
                if (const double margin =
                        scene.sides[k][hi]->pictureMargin(setup.wallLayers, scene.spacing))
                    (hi ? render_.max[k] : render_.min[k]) += (hi ? 1 : -1) * margin;
    }
    render_.spacing = scene.spacing;
    render_.width = scene.output.imageWidth;
    render_.title = scene.name;
    const sph::Vector<Dim> g = setup.gravity(1e300);
    for (int k = 0; k < Dim; ++k)
        if (std::abs(g[k]) > std::abs(g[render_.upAxis]) + 1e-300) render_.upAxis = k;
    double lo = 1e300, hi = -1e300;
    const auto T = initial.template getValue<double>(QuantityId::TEMPERATURE);
    const auto kind = initial.template getValue<int>(QuantityId::KIND);
    for (sph::Size i = 0; i < initial.size(); ++i)
        if (kind[i] != int(sph::ParticleKind::WALL))
            lo = std::min(lo, T[i]), hi = std::max(hi, T[i]);
    for (int k = 0; k < Dim; ++k)
        for (int h = 0; h < 2; ++h)
            if (const auto held = scene.sides[k][h]->heldTemperature())
                lo = std::min(lo, *held), hi = std::max(hi, *held);
    for (const auto& e : scene.emitters)
        lo = std::min(lo, e.temperature), hi = std::max(hi, e.temperature);
    if (!(hi > lo)) lo = (lo < 1e299 ? lo : 20) - 1, hi = lo + 2;
    render_.colorMin = scene.output.colorMin.value_or(lo);
    render_.colorMax = scene.output.colorMax.value_or(hi);
}

template <int Dim>
std::string Outputs<Dim>::fileName(int index, const std::string& extension) const {
    return scene_.output.prefix + formatted("_%04d.", index) + extension;
}

template <int Dim>
void Outputs<Dim>::writeParaviewScript() const {
    if (!scene_.output.vtu) return;
    ParaviewView v;
    v.pvdName = scene_.output.prefix + ".pvd";
    v.dimension = Dim;
    v.upAxis = Dim == 2 ? 1 : render_.upAxis;
    v.spacing = scene_.spacing;
    v.colorMin = render_.colorMin, v.colorMax = render_.colorMax;
    num::io::writeParaviewScript(path(scene_.output.prefix + "_paraview.py"), v);
}

template <int Dim>
bool Outputs<Dim>::earlierRunFile(const std::string& name) const {
    const std::string& prefix = scene_.output.prefix;
    for (const std::string& own :
         {prefix + ".pvd", prefix + ".mp4", std::string("probes.csv"), std::string("probes.png"),
          std::string("summary.json"), std::string("checkpoint_interrupted.chk")})
        if (name == own) return true;
    // prefix_NNNN.vtu, .csv, .png and checkpoint_NNNN.chk: at least four digits.
    auto numbered = [&](const std::string& head, std::initializer_list<const char*> extensions) {
        if (name.rfind(head, 0) != 0) return false;
        const std::size_t dot = name.rfind('.');
        if (dot == std::string::npos || dot < head.size() + 4) return false;
        for (std::size_t k = head.size(); k < dot; ++k)
            if (!std::isdigit((unsigned char)name[k])) return false;
        for (const char* e : extensions)
            if (name.compare(dot + 1, std::string::npos, e) == 0) return true;
        return false;
    };
    return numbered(prefix + "_", {"vtu", "csv", "png"}) || numbered("checkpoint_", {"chk"});
}

template <int Dim>
void Outputs<Dim>::removeEarlierRun() {
    namespace fs = std::filesystem;
    std::error_code ec;
    std::vector<std::string> names;
    for (fs::directory_iterator it(dir_, ec), end; !ec && it != end; it.increment(ec)) {
        std::error_code fileEc;
        const std::string name = it->path().filename().string();
        if (it->is_regular_file(fileEc) && earlierRunFile(name)) names.push_back(name);
    }
    std::sort(names.begin(), names.end());
    std::size_t removed = 0;
    for (const std::string& name : names) removed += std::remove(path(name).c_str()) == 0;
    if (removed == 0) return;
    earlierRunNote_ = dir_ + ": removed " + std::to_string(removed) +
                      " files an earlier run wrote under the names this run writes (" +
                      names.front() + (names.size() > 1 ? " ... " + names.back() : "") +
                      "), so that its series, movie and checkpoints are this run's alone; give "
                      "another --out to keep an earlier run's files";
}

template <int Dim>
void Outputs<Dim>::start() {
    makeOutputDirectory(dir_);
    removeEarlierRun();
    writeParaviewScript();
    if (scene_.probes.empty()) return;
    // Quoted where needed (RFC 4180), although probe names are plain words.
    auto field = [](const std::string& name) {
        if (name.find_first_of(",\"\r\n") == std::string::npos) return name;
        std::string q = "\"";
        for (char c : name) q += c == '"' ? std::string("\"\"") : std::string(1, c);
        return q + "\"";
    };
    std::string header = "time";
    const char* axes = "xyz";
    for (const auto& p : scene_.probes)
        for (const auto& f : p.fields) {
            if (f == "velocity")
                for (int k = 0; k < Dim; ++k)
                    header += "," + field(p.name + ".v" + std::string(1, axes[k]));
            else
                header += "," + field(p.name + "." + f);
        }
    writeFileAtomically(path("probes.csv"), header + "\n");
}

template <int Dim>
void Outputs<Dim>::resume(double t, std::vector<std::pair<double, std::string>> series) {
    makeOutputDirectory(dir_);
    writeParaviewScript();
    for (auto& [time, file] : series) series_.add(time, file);
    series_.truncateAfter(t);
    pictures_ = int(series_.entries().size());
    if (scene_.probes.empty()) return;
    std::ifstream in(path("probes.csv"));
    if (!in) return start();
    std::string line, kept;
    bool header = true;
    while (std::getline(in, line)) {
        if (!header && std::strtod(line.c_str(), nullptr) > t * (1 + 1e-12)) break;
        kept += line + "\n";
        header = false;
    }
    writeFileAtomically(path("probes.csv"), kept);
}

template <int Dim>
void Outputs<Dim>::write(const sph::Storage<Dim>& s, double t, int index) {
    const std::vector<OutputField> fields = outputFields(s, names_);
    const OutputSpec& o = scene_.output;
    if (o.vtu) {
        writeVtu(path(fileName(index, "vtu")), s, fields, t);
        series_.truncateAfter(t - 1e-12 * std::max(1.0, std::abs(t)));
        series_.add(t, fileName(index, "vtu"));
        series_.write(path(o.prefix + ".pvd"));
    }
    if (o.csv) writeCsv(path(fileName(index, "csv")), s, fields);
    if (o.images) {
        writePng(path(fileName(index, "png")), renderParticles(s, render_, t));
        pictures_ = index + 1;
    }
    writeProbes(s, t);
}

template <int Dim>
void Outputs<Dim>::writeProbes(const sph::Storage<Dim>& s, double t) {
    if (scene_.probes.empty()) return;
    const sph::RunKernel<Dim> kernel(setup_.settings);
    std::string row = formatted("%.10g", t);
    for (const auto& p : scene_.probes)
        for (const auto& f : p.fields)
            for (double v : probe(s, kernel, p.point, f)) row += formatted(",%.10g", v);
    row += "\n";
    appendToFile(path("probes.csv"), row);
}

template <int Dim>
std::string Outputs<Dim>::makeVideo() const {
    if (!onPath("ffmpeg"))
        return "ffmpeg is not installed (./scripts/setup.sh or apt-get install ffmpeg adds it)";
    auto quote = [](const std::string& s) {
        std::string q = "'";
        for (char c : s) q += c == '\'' ? std::string("'\\''") : std::string(1, c);
        return q + "'";
    };
    const int fps = std::clamp(pictures_ / 8, 5, 30);
    const std::string video = path(scene_.output.prefix + ".mp4");
    const std::string log = path("ffmpeg.log");
    // Written under a temporary name and renamed, like every other output.
    // This run's pictures only: a restart that ends before the run it continues leaves that
    // run's later pictures in the folder.
    const std::string cmd = "ffmpeg -y -nostdin -loglevel error -framerate " + std::to_string(fps) +
                            " -i " + quote(path(scene_.output.prefix + "_%04d.png")) +
                            " -frames:v " + std::to_string(pictures_) +
                            " -vf 'pad=ceil(iw/2)*2:ceil(ih/2)*2' -pix_fmt yuv420p -f mp4 " +
                            quote(video + ".tmp") + " >" + quote(log) + " 2>&1";
    const int rc = std::system(cmd.c_str());
    std::ifstream in(log);
    std::string firstLine;
    std::getline(in, firstLine);
    in.close();
    std::remove(log.c_str());
    if (rc != 0 || std::rename((video + ".tmp").c_str(), video.c_str()) != 0) {
        std::remove((video + ".tmp").c_str());
        return "ffmpeg failed" + (firstLine.empty() ? std::string() : ": " + firstLine);
    }
    return "";
}

template <int Dim>
EndOfRun Outputs<Dim>::finish(bool completed) const {
    EndOfRun end;
    if (scene_.output.vtu) end.paraviewScript = path(scene_.output.prefix + "_paraview.py");
    if (!scene_.probes.empty()) {
        std::ifstream in(path("probes.csv"), std::ios::binary);
        std::ostringstream csv;
        csv << in.rdbuf();
        end.probePlot = path("probes.png");
        writePng(end.probePlot, plotProbes(csv.str(), "probes: " + scene_.name,
                                           std::max(640, scene_.output.imageWidth)));
    }
    end.videoWanted = scene_.output.images && scene_.output.video;
    if (!scene_.output.images)
        end.videoNote = "output.images is false";
    else if (!scene_.output.video)
        end.videoNote = "output.video is false";
    else if (!completed)
        end.videoNote = "the run did not complete";
    else if (pictures_ < 2)
        end.videoNote = "fewer than 2 pictures";
    else
        end.videoNote = makeVideo();
    if (end.videoNote.empty()) end.video = path(scene_.output.prefix + ".mp4");
    return end;
}

template class Outputs<2>;
template class Outputs<3>;

}  // namespace num::io
