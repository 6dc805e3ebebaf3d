// A plugin whose terms fail on purpose, one way each, for the tests of the apps' errors:
//   throws_when_made   its factory throws;
//   throws_in_create   create() throws (set-up);
//   throws_in_step     finalize() throws from time "after" [s] on;
//   only_2d            a term registered for 2D only;
//   reads_strength     reads an optional "strength" without allow().
#include <stdexcept>
#include <tuple>

#include "io/plugin.hpp"

namespace {

using namespace num::sph;

enum class When { NEVER, CREATE, STEP };

template <int Dim>
class Faulty : public IEquationTerm<Dim> {
  public:
    Faulty(When when, Float after) : when_(when), after_(after) {}
    void setDerivatives(DerivativeHolder<Dim>&, const RunSettings&) override {}
    void initialize(IScheduler&, Storage<Dim>&, Float) override {}
    void finalize(IScheduler&, Storage<Dim>&, Float t) override {
        if (when_ == When::STEP && t >= after_)
            throw std::runtime_error("the test term gives up at t >= " + std::to_string(after_));
    }
    void create(Storage<Dim>&, IMaterial&) const override {
        if (when_ == When::CREATE) throw std::runtime_error("the test term refuses to be created");
    }

  private:
    When when_;
    Float after_;
};

}  // namespace

NUMERICS_PLUGIN(registry) {
    using P = num::io::plugin::Parameters;
    registry.add<Faulty>("throws_when_made", [](const P&) -> std::tuple<When, Float> {
        throw std::runtime_error("the test factory refuses its parameters");
    });
    registry.add<Faulty>("throws_in_create", [](const P& p) {
        p.allow({});
        return std::tuple{When::CREATE, 0.0};
    });
    registry.add<Faulty>("throws_in_step", [](const P& p) {
        p.allow({"after"});
        return std::tuple{When::STEP, p.number("after", 0, 1e300, "s")};
    });
    registry.addOne<Faulty<2>>("only_2d", [](const P&) { return std::tuple{When::NEVER, 0.0}; });
    registry.add<Faulty>("reads_strength", [](const P& p) {
        p.number("strength", 1.0, 0, 10);
        return std::tuple{When::NEVER, 0.0};
    });
}
