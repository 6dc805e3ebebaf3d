// The example plugins (examples/plugins) run end to end through fluid_sim and fluid_sim_3d on
// their scenes, each checked against an analytic value.
#include <cmath>
#include <numbers>

#include "plugin_test_support.hpp"

namespace {

using plugintest::json;

template <int Dim>
const char* app() {
    return Dim == 2 ? FLUID_SIM : FLUID_SIM_3D;
}

/// The spring plugin: the drop's centre of mass is a harmonic oscillator, X'' = -(k/m) X, since
/// the fluid's pair forces cancel in the sum over particles (no walls: a periodic box; no
/// shifting, which moves particles without forces). X(t) = X0 cos(omega t), omega = sqrt(k/m).
/// Tolerance: leapfrog's phase error for a harmonic oscillator is omega t (omega dt)^2 / 24
/// (Hairer, Lubich & Wanner, Geometric Numerical Integration, 2006, sec. I.5); the spring term
/// limits dt <= 1 / (20 omega), so over one period the error is below 2 pi / 9600 = 6.5e-4 of
/// X0: we allow 1e-3 X0. A period wrong by 2e-4 already fails.
template <int Dim>
void springPeriod() {
    const std::string dir = apptest::freshDir("spring_" + std::to_string(Dim) + "d");
    json scene = plugintest::exampleScene("spring_" + std::to_string(Dim) + "d.json");
    scene["plugins"][0]["library"] = SPRING_PLUGIN;
    const auto r = plugintest::runScene(app<Dim>(), scene, dir);
    ASSERT_EQ(r.code, 0) << r.output;

    const double k = scene["plugins"][0]["terms"][0]["stiffness"];
    const double every = scene["output"]["every"], end = scene["time"]["end"];
    const auto first = plugintest::output(dir, 0);
    const double m = first.at("mass").at(0), x0 = plugintest::mean(first.at("x"));
    const double omega = std::sqrt(k / m);
    EXPECT_NEAR(2 * std::numbers::pi / omega, 0.5, 1e-9) << "the scene states a 0.5 s period";
    const int outputs = int(std::lround(end / every));
    ASSERT_GE(outputs, 16);
    for (int n = 0; n <= outputs; ++n) {
        const double t = n * every;
        const double x = plugintest::mean(plugintest::output(dir, n).at("x"));
        EXPECT_NEAR(x, x0 * std::cos(omega * t), 1e-3 * x0) << Dim << "D, t = " << t;
    }
    // summary.json lists the evaluation's passes: the spring, which declares nothing, runs in
    // the one pass of the fluid terms, named by its label.
    const json summary = json::parse(apptest::readFile(dir + "/out/summary.json"));
    ASSERT_EQ(summary["passes"].size(), 1u) << summary["passes"].dump();
    int springs = 0;
    for (const auto& name : summary["passes"][0])
        springs += name.get<std::string>().find("term \"spring\" (plugins.0.terms.0") == 0;
    EXPECT_EQ(springs, 1) << summary["passes"].dump();
}

TEST(PluginExamples, SpringPeriod2D) { springPeriod<2>(); }
TEST(PluginExamples, SpringPeriod3D) { springPeriod<3>(); }

/// The heat source plugin: water at rest, conduction off. Energy balance: the thermal energy
/// sum_i m_i c T_i grows at the power sum_i q V_i, V_i = 1 / sum_j W_ij. On the particle lattice
/// in the source box (n points, n dx^Dim = its volume V) that power is q V / S, with S the
/// lattice sum sum_j W_ij dx^Dim of the default kernel (Wendland C2, h = 1.5 dx): 1.005142 in
/// 2D, 1.003141 in 3D (docs/reference_solutions.md, section 1; tests/kernels): the power is
/// checked to 2e-6 (the table's last digit). The energy balance holds exactly in the scheme
/// (dT/dt is constant in time); the CSV's 10 significant digits of T ~ 20 degC bound the error
/// of an energy difference to 1e-8 K * sum m c, below 1e-5 of the heat put in by the first
/// output: checked to 2e-5.
template <int Dim>
void heatSourceEnergyBalance() {
    const std::string dir = apptest::freshDir("heat_source_" + std::to_string(Dim) + "d");
    json scene = plugintest::exampleScene("heat_source_" + std::to_string(Dim) + "d.json");
    scene["plugins"][0]["library"] = HEAT_SOURCE_PLUGIN;
    const auto r = plugintest::runScene(app<Dim>(), scene, dir);
    ASSERT_EQ(r.code, 0) << r.output;

    const json& term = scene["plugins"][0]["terms"][0];
    const double q = term["power_density"], c = scene["materials"]["water"]["heat_capacity"];
    double volume = 1;
    for (int k = 0; k < Dim; ++k) volume *= double(term["max"][k]) - double(term["min"][k]);
    const double latticeSum = Dim == 2 ? 1.005142 : 1.003141;
    const double every = scene["output"]["every"];
    auto energy = [&](const plugintest::Table& t) {
        double e = 0;
        for (std::size_t i = 0; i < t.at("mass").size(); ++i)
            e += t.at("mass")[i] * c * t.at("temperature")[i];
        return e;
    };
    const auto first = plugintest::output(dir, 0);
    const double e0 = energy(first);
    double power = 0;  // the field the scene names: each particle's q V_i
    for (double p : first.at("heat_source_power")) power += p;
    EXPECT_NEAR(power, q * volume / latticeSum, 2e-6 * q * volume);
    for (int n = 1; n <= 4; ++n) {
        const double t = n * every;
        EXPECT_NEAR(energy(plugintest::output(dir, n)) - e0, power * t, 2e-5 * power * t)
            << Dim << "D, t = " << t;
    }
}

TEST(PluginExamples, HeatSourceEnergyBalance2D) { heatSourceEnergyBalance<2>(); }
TEST(PluginExamples, HeatSourceEnergyBalance3D) { heatSourceEnergyBalance<3>(); }

}  // namespace
