// A plugin with writers and no terms: "particle_count" writes <prefix>_NNNN.txt at every output
// (the time, the particles and the fields written) and logs its calls to particle_count.log;
// "fails_at_second_output" throws a std::runtime_error when it writes output number 2.
#include <stdexcept>
#include <string>

#include "app/file.hpp"
#include "app/plugin.hpp"

namespace {

template <int Dim>
class ParticleCountWriter : public num::app::IWriter<Dim> {
  public:
    explicit ParticleCountWriter(const num::app::WriterContext& context) : c_(context) {}

    void start() override { num::app::writeFileAtomically(log(), "start\n"); }
    void resume(double t, const num::app::OutputSeries&) override {
        num::app::appendToFile(log(), num::app::formatted("resume %g\n", t));
    }
    void write(const num::sph::Storage<Dim>& s, const std::vector<num::app::OutputField>& fields,
               double t, int index) override {
        std::string text = num::app::formatted("dimension %d\ntime %.6g\nparticles %zu\nfields",
                                               Dim, t, std::size_t(s.size()));
        for (const auto& f : fields) text += " " + f.name;
        num::app::writeFileAtomically(c_.path(c_.fileName(index, "txt")), text + "\n");
        num::app::appendToFile(log(), num::app::formatted("write %d\n", index));
    }
    void finish(bool completed, num::app::EndOfRun&) override {
        num::app::appendToFile(log(), completed ? "finish completed\n" : "finish stopped\n");
    }
    std::vector<num::app::WrittenFile> files() const override {
        return {{c_.prefix + "_*.txt", "particle counts"}};
    }

  private:
    std::string log() const { return c_.path("particle_count.log"); }
    num::app::WriterContext c_;
};

template <int Dim>
class FailingWriter : public num::app::IWriter<Dim> {
  public:
    explicit FailingWriter(const num::app::WriterContext&) {}
    void write(const num::sph::Storage<Dim>&, const std::vector<num::app::OutputField>&, double,
               int index) override {
        if (index == 2) throw std::runtime_error("no room for output 2");
    }
};

}  // namespace

NUMERICS_PLUGIN(registry) {
    registry.addWriter<ParticleCountWriter>("particle_count");
    registry.addWriter<FailingWriter>("fails_at_second_output");
}
