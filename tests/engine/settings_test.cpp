// Typed settings: defaults, validation messages, and materials.
#include <gtest/gtest.h>

#include <functional>
#include <string>

#include "numerics.hpp"
#include "sph/equation_of_state_choice.hpp"
#include "sph/evaluation_mode.hpp"
#include "sph/integrator_choice.hpp"
#include "sph/kernel_choice.hpp"

namespace {

using namespace num::sph;

std::string messageOf(const std::function<void()>& f) {
    try {
        f();
    } catch (const SettingsError& e) {
        return e.what();
    }
    return "no error";
}

TEST(Settings, DefaultsAndTypedAccess) {
    RunSettings s;
    EXPECT_EQ(s.get<std::string>("evaluation"), "asymmetric");
    s.set("smoothing_length", 2).set("threads", 3).set("kernel", "cubic_spline");
    EXPECT_EQ(s.get<double>("smoothing_length"), 2.0);  // an integer is accepted for a real
    EXPECT_EQ(s.get<int>("threads"), 3);
    EXPECT_EQ(s.get<std::string>("kernel"), "cubic_spline");
}

TEST(Settings, UnknownKeySuggestsTheNearestKey) {
    RunSettings s;
    const std::string m = messageOf([&] { s.set("smoothing_lenght", 0.1); });
    EXPECT_NE(m.find("unknown setting 'smoothing_lenght'"), std::string::npos) << m;
    EXPECT_NE(m.find("did you mean 'smoothing_length'"), std::string::npos) << m;
    const std::string far = messageOf([&] { s.get<double>("zzzzzzzzzz"); });
    EXPECT_NE(far.find("unknown setting"), std::string::npos) << far;
    EXPECT_EQ(far.find("did you mean"), std::string::npos) << far;
}

TEST(Settings, WrongTypeNamesExpectedAndFound) {
    RunSettings s;
    const std::string m = messageOf([&] { s.set("threads", "four"); });
    EXPECT_NE(m.find("'threads': expected integer, got string"), std::string::npos) << m;
    EXPECT_NE(messageOf([&] { s.set("threads", 2.5); }).find("expected integer"),
              std::string::npos);
    EXPECT_NE(messageOf([&] { s.get<std::string>("cfl"); }).find("'cfl' is a number"),
              std::string::npos);
}

TEST(Settings, OutOfRangeAndChoices) {
    RunSettings s;
    const std::string m = messageOf([&] { s.set("cfl", 2.0); });
    EXPECT_NE(m.find("'cfl'"), std::string::npos) << m;
    EXPECT_NE(m.find("outside"), std::string::npos) << m;
    EXPECT_NE(messageOf([&] { s.set("threads", 0); }).find("outside"), std::string::npos);
    const std::string k = messageOf([&] { s.set("kernel", "gaussian"); });
    EXPECT_NE(k.find("'gaussian' is not one of cubic_spline"), std::string::npos) << k;
    EXPECT_EQ(s.get<double>("cfl"), 0.25);  // a rejected value leaves the old one
}

TEST(Settings, MaterialParameters) {
    Material water;
    EXPECT_EQ(water.name(), "water");
    water.params().set("density", 998.0);
    EXPECT_EQ(water.params().get<double>("density"), 998.0);
    EXPECT_NE(messageOf([&] { water.params().set("density", -1.0); }).find("outside"),
              std::string::npos);
    EXPECT_NE(messageOf([&] { water.params().set("densty", 1.0); }).find("did you mean 'density'"),
              std::string::npos);
}

TEST(Settings, UnknownNamesOfKernelIntegratorAndBackend) {
    EXPECT_THROW(kernelFromName("gauss"), SettingsError);
    EXPECT_THROW(makeIntegrator<2>("rk4"), SettingsError);
    EXPECT_THROW(makeScheduler("cuda", 2), std::invalid_argument);
    EXPECT_EQ(makeScheduler("omp", 3)->threadCount(), 3u);
    EXPECT_EQ(makeScheduler("seq", 3)->threadCount(), 1u);
}

// Every table's entry dispatches to its own alternative, and an unknown name is refused with a
// message that lists every name of the table.
template <class Table>
void expectTheMessageListsTheTable(const std::string& message, const Table& table) {
    for (const std::string& name : choiceNames(table))
        EXPECT_NE(message.find(name), std::string::npos) << message;
}

template <int Dim>
void expectEveryKernelDispatches() {
    for (std::size_t i = 0; i < std::tuple_size_v<decltype(kernelTable)>; ++i)
        withChoice(kernelTable, i, [&](auto entry) {
            const KernelType type = kernelFromName(std::string(entry.name));
            EXPECT_EQ(type.index, i) << entry.name;
            withKernel<Dim>(type, [&](auto kernel) {
                using Expected = typename decltype(entry)::template type<Dim>;
                EXPECT_TRUE((std::is_same_v<decltype(kernel), Expected>)) << entry.name;
            });
        });
}

TEST(Choices, EveryKernelDispatches) {
    expectEveryKernelDispatches<1>();
    expectEveryKernelDispatches<2>();
    expectEveryKernelDispatches<3>();
    RunSettings s;
    expectTheMessageListsTheTable(messageOf([&] { kernelFromName("gauss"); }), kernelTable);
    expectTheMessageListsTheTable(messageOf([&] { s.set("kernel", "gauss"); }), kernelTable);
    expectTheMessageListsTheTable(s.specs().at("kernel").help, kernelTable);
    expectTheMessageListsTheTable(s.specs().at("evaluation").help, evaluationTable);
}

TEST(Choices, EveryIntegratorDispatches) {
    for (const std::string& name : choiceNames(integratorTable)) {
        EXPECT_EQ(makeIntegrator<2>(name)->name(), name);
        EXPECT_EQ(makeIntegrator<3>(name)->name(), name);
    }
    expectTheMessageListsTheTable(messageOf([&] { makeIntegrator<2>("rk4"); }), integratorTable);
}

TEST(Choices, EveryEvaluationAndEquationOfStateDispatches) {
    for (const auto& choice : evaluationTable)
        EXPECT_EQ(evaluationFromName(std::string(choice.name)), choice.value);
    for (const auto& choice : eosTable)
        EXPECT_EQ(eosFromName(std::string(choice.name)), choice.value);
    RunSettings s;
    expectTheMessageListsTheTable(messageOf([&] { evaluationFromName("pairs"); }), evaluationTable);
    expectTheMessageListsTheTable(messageOf([&] { s.set("evaluation", "pairs"); }),
                                  evaluationTable);
    expectTheMessageListsTheTable(messageOf([&] { eosFromName("ideal_gas"); }), eosTable);
    EXPECT_EQ(defaultKernel, kernelFromName(defaults::kernel));
    EXPECT_EQ(defaultEos, eosFromName(defaults::eos));
}

}  // namespace
