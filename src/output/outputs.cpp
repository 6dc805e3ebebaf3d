#include "app/outputs.hpp"

#include <unistd.h>

#include <algorithm>
#include <cctype>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <sstream>

#include "app/file.hpp"
#include "output/bodies_writer.hpp"
#include "output/pictures_writer.hpp"
#include "output/probes_writer.hpp"

namespace num::app {

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

namespace {

/// The pictures' view: the domain (2D with its wall layers), colours over the scene's
/// temperatures (those of the initial fluid, fixed-temperature walls and emitters).
template <int Dim>
RenderSettings<Dim> renderSettings(const Scene<Dim>& scene, const SceneSetup<Dim>& setup,
                                   const sph::Storage<Dim>& initial) {
    RenderSettings<Dim> render;
    render.min = scene.domainMin, render.max = scene.domainMax;
    if constexpr (Dim == 2) {
        for (int k = 0; k < Dim; ++k)
            for (int hi = 0; hi < 2; ++hi)
                if (const double margin =
                        scene.sides[k][hi]->pictureMargin(setup.wallLayers, scene.spacing))
                    (hi ? render.max[k] : render.min[k]) += (hi ? 1 : -1) * margin;
    }
    render.spacing = scene.spacing;
    render.width = scene.output.imageWidth;
    render.title = scene.name;
    const sph::Vector<Dim> g = setup.gravity(1e300);
    for (int k = 0; k < Dim; ++k)
        if (std::abs(g[k]) > std::abs(g[render.upAxis]) + 1e-300) render.upAxis = k;
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
    for (const auto& w : scene.walls)
        if (const auto held = w.boundary->heldTemperature())
            lo = std::min(lo, *held), hi = std::max(hi, *held);
    for (const auto& e : scene.emitters)
        lo = std::min(lo, e.temperature), hi = std::max(hi, e.temperature);
    if (!(hi > lo)) lo = (lo < 1e299 ? lo : 20) - 1, hi = lo + 2;
    render.colorMin = scene.output.colorMin.value_or(lo);
    render.colorMax = scene.output.colorMax.value_or(hi);
    return render;
}

/// The forces on the bodies and then the interior walls, where a probe records one.
template <int Dim>
std::optional<BodyForces<Dim>> bodyForces(const Scene<Dim>& scene, const SceneSetup<Dim>& setup) {
    if (std::none_of(scene.probes.begin(), scene.probes.end(),
                     [](const Probe<Dim>& p) { return p.body >= 0 || p.wall >= 0; }))
        return std::nullopt;
    const auto& bodies = setup.geometry.bodies;
    const auto& walls = setup.geometry.interiorWalls;
    // A body's particles carry their body's index where bodies move; else, as walls, the
    // solid that holds them.
    auto targetOf = [bodies, walls](const sph::Storage<Dim>& s, sph::Size j) {
        const int kind = s.template getValue<int>(sph::QuantityId::KIND)[j];
        const auto x = s.template getValue<sph::Vector<Dim>>(sph::QuantityId::POSITION)[j];
        if (kind == int(sph::ParticleKind::BODY)) {
            if (s.has(sph::QuantityId::BODY_INDEX))
                return s.template getValue<int>(sph::QuantityId::BODY_INDEX)[j];
            for (std::size_t b = 0; b < bodies.size(); ++b)
                if (bodies[b].contains(x)) return int(b);
        } else if (kind == int(sph::ParticleKind::WALL)) {
            for (std::size_t w = 0; w < walls.size(); ++w)
                if (walls[w].contains(x)) return int(bodies.size() + w);
        }
        return -1;
    };
    return BodyForces<Dim>(setup.settings, setup.geometry.domain, int(bodies.size() + walls.size()),
                           targetOf, setup.model.artificialViscosity, setup.model.c0());
}

}  // namespace

template <int Dim>
Outputs<Dim>::Outputs(const Scene<Dim>& scene, const SceneSetup<Dim>& setup, std::string directory,
                      const sph::Storage<Dim>& initial, FieldNames names,
                      const WriterRegistry& writers)
    : scene_(scene), dir_(std::move(directory)), names_(std::move(names)) {
    while (dir_.size() > 1 && dir_.back() == '/') dir_.pop_back();
    makeWriters(scene, setup, initial, writers);
}

template <int Dim>
void Outputs<Dim>::makeWriters(const Scene<Dim>& scene, const SceneSetup<Dim>& setup,
                               const sph::Storage<Dim>& initial, const WriterRegistry& writers) {
    checkOutputFormats<Dim>(scene.file, scene.output.formats, writers);
    const RenderSettings<Dim> render = renderSettings(scene, setup, initial);
    WriterContext& context = context_;
    context.directory = dir_, context.prefix = scene.output.prefix, context.title = scene.name;
    context.spacing = scene.spacing, context.upAxis = render.upAxis;
    context.colorMin = render.colorMin, context.colorMax = render.colorMax;
    for (const std::string& format : scene.output.formats)
        writers_.push_back(writers.make<Dim>(format, context));
    if (scene.output.images) {
        auto pictures = std::make_unique<PicturesWriter<Dim>>(context, render, scene.output.video);
        pictures_ = pictures.get();
        writers_.push_back(std::move(pictures));
    }
    if (setup.model.movingBodies)
        writers_.push_back(std::make_unique<BodiesWriter<Dim>>(context, setup.model.movingBodies,
                                                               scene.output.plots));
    if (!scene.probes.empty()) {
        auto probes = std::make_unique<ProbesWriter<Dim>>(
            context, scene.probes, setup.settings, scene.output.plots,
            std::array<sph::Vector<Dim>, 2>{scene.domainMin, scene.domainMax}, scene.spacing,
            bodyForces(scene, setup), int(setup.geometry.bodies.size()));
        probes_ = probes.get();
        writers_.push_back(std::move(probes));
    }
}

template <int Dim>
std::string Outputs<Dim>::fileName(int index, const std::string& extension) const {
    return context_.fileName(index, extension);
}

template <int Dim>
bool Outputs<Dim>::earlierRunFile(const std::string& name) const {
    const std::string& prefix = scene_.output.prefix;
    for (const std::string& own :
         {prefix + ".pvd", prefix + ".mp4", std::string("probes.csv"), std::string("probes.png"),
          std::string("bodies.csv"), std::string("bodies.png"), std::string("bodies.svg"),
          std::string("probes.svg"), std::string("summary.json"),
          std::string("checkpoint_interrupted.chk")})
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
    lock_ = std::make_unique<OutputLock>(dir_);  // before any file of the directory is touched
    removeEarlierRun();
    for (auto& w : writers_) w->start();
}

template <int Dim>
void Outputs<Dim>::resume(double t, std::vector<std::pair<double, std::string>> series) {
    makeOutputDirectory(dir_);
    lock_ = std::make_unique<OutputLock>(dir_);
    PvdSeries kept;
    for (auto& [time, file] : series) kept.add(time, file);
    kept.truncateAfter(t);
    for (auto& w : writers_) w->resume(t, kept.entries());
}

template <int Dim>
void Outputs<Dim>::write(const sph::Storage<Dim>& s, double t, int index) {
    const std::vector<OutputField> fields = outputFields(s, names_);
    for (auto& w : writers_)
        if (w.get() != probes_) w->write(s, fields, t, index);  // probes: at their own times
}

template <int Dim>
void Outputs<Dim>::writeProbes(const sph::Storage<Dim>& s, double t) {
    if (probes_) probes_->write(s, {}, t, 0);
}

template <int Dim>
EndOfRun Outputs<Dim>::finish(bool completed) const {
    EndOfRun end;
    for (const auto& w : writers_) w->finish(completed, end);
    if (!pictures_) end.videoNote = "output.images is false";
    return end;
}

template <int Dim>
std::vector<WrittenFile> Outputs<Dim>::files() const {
    std::vector<WrittenFile> out;
    for (const auto& w : writers_)
        for (WrittenFile& f : w->files()) out.push_back(std::move(f));
    return out;
}

template <int Dim>
const PvdSeries& Outputs<Dim>::series() const {
    static const PvdSeries none;
    for (const auto& w : writers_)
        if (const PvdSeries* s = w->series()) return *s;
    return none;
}

template <int Dim>
int Outputs<Dim>::pictures() const {
    return pictures_ ? pictures_->pictures() : 0;
}

template class Outputs<2>;
template class Outputs<3>;

}  // namespace num::app
