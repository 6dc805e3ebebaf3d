// A plugin whose terms fail on purpose, one way each, for the tests of the apps' errors:
//   throws_when_made   its factory throws;
//   throws_int_when_made   its factory throws an int (not a std::exception);
//   throws_in_create   create() throws (set-up);
//   throws_in_step     finalize() throws from time "after" [s] on;
//   only_2d            a term registered for 2D only;
//   reads_strength     reads an optional "strength" without allow();
//   leaves_its_range   creates the field "level" (declared in [0, 1]) and raises it by "rate"
//                      [1/s] each step, so that it leaves its range.
#include <stdexcept>
#include <tuple>

#include "app/plugin.hpp"

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

/// A quantity that grows at `rate` per second on every particle.
constexpr auto kLevel = QuantityId(1001);
template <int Dim>
class Drift : public IEquationTerm<Dim> {
  public:
    explicit Drift(Float rate) : rate_(rate) {}
    void setDerivatives(DerivativeHolder<Dim>&, const RunSettings&) override {}
    void initialize(IScheduler&, Storage<Dim>&, Float) override {}
    void finalize(IScheduler&, Storage<Dim>&, Float) override {}
    void postStep(IScheduler&, Storage<Dim>& s, Float, Float dt) override {
        for (Float& x : s.template getValue<Float>(kLevel)) x += rate_ * dt;
    }
    void create(Storage<Dim>& s, IMaterial&) const override {
        s.template insert<Float>(kLevel, OrderEnum::ZERO, 0.0);
    }

  private:
    Float rate_;
};

}  // namespace

NUMERICS_PLUGIN(registry) {
    using P = num::app::plugin::Parameters;
    registry.add<Faulty>("throws_when_made", [](const P&) -> std::tuple<When, Float> {
        throw std::runtime_error("the test factory refuses its parameters");
    });
    registry.add<Faulty>("throws_int_when_made",
                         [](const P&) -> std::tuple<When, Float> { throw 7; });
    registry.add<Faulty>("throws_in_create", [](const P& p) {
        p.allow({});
        return std::tuple{When::CREATE, 0.0};
    });
    registry.add<Faulty>("throws_in_step", [](const P& p) {
        p.allow({"after"});
        return std::tuple{When::STEP, p.number("after", 0, 1e300, "s")};
    });
    registry.addOne<Faulty<2>>("only_2d", [](const P&) { return std::tuple{When::NEVER, 0.0}; });
    registry.add<Drift>("leaves_its_range", [](const P& p) {
        p.allow({"rate"});
        return std::tuple{p.number("rate", 0, 1e6, "1/s")};
    });
    registry.addField("level", kLevel, 0, 1, "");
    registry.add<Faulty>("reads_strength", [](const P& p) {
        p.number("strength", 1.0, 0, 10);
        return std::tuple{When::NEVER, 0.0};
    });
}
