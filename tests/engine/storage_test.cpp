// Storage: insert, typed access, user quantity ids, and consistency of every quantity and
// derivative level under reorder, remove, append and gather.
#include <gtest/gtest.h>

#include <memory>
#include <tuple>
#include <vector>

#include "numerics.hpp"

namespace {

using namespace num::sph;
using V2 = Vector<2>;

enum class AdditionalId : int { MY_SCALAR = -7 };
constexpr auto MY_SCALAR = QuantityId(AdditionalId::MY_SCALAR);

/// A storage whose every entry encodes its particle: value 100 i + level (and offset).
Storage<2> encoded(Size n, double offset = 0) {
    Storage<2> s;
    std::vector<V2> x(n);
    std::vector<double> e(n);
    std::vector<int> kind(n);
    for (Size i = 0; i < n; ++i) {
        x[i] = V2{{100.0 * i + offset, -1.0 * i}};
        e[i] = 100.0 * i + offset;
        kind[i] = int(i + offset);
    }
    s.insert<V2>(QuantityId::POSITION, OrderEnum::SECOND, x);
    s.insert<double>(QuantityId::ENERGY, OrderEnum::FIRST, e);
    s.insert<int>(QuantityId::KIND, OrderEnum::ZERO, kind);
    s.insert<double>(MY_SCALAR, OrderEnum::ZERO, e);
    for (Size i = 0; i < n; ++i) {
        s.getDt<V2>(QuantityId::POSITION)[i] = x[i] + V2{{1, 0}};
        s.getD2t<V2>(QuantityId::POSITION)[i] = x[i] + V2{{2, 0}};
        s.getDt<double>(QuantityId::ENERGY)[i] = e[i] + 1;
    }
    return s;
}

/// Checks that particle k of s is the particle `origin[k]` of encoded(...).
void expectParticles(const Storage<2>& s, const std::vector<double>& origin) {
    ASSERT_EQ(s.size(), origin.size());
    for (Size k = 0; k < s.size(); ++k) {
        const double o = origin[k];
        EXPECT_EQ(s.getValue<V2>(QuantityId::POSITION)[k][0], o);
        EXPECT_EQ(s.getDt<V2>(QuantityId::POSITION)[k][0], o + 1);
        EXPECT_EQ(s.getD2t<V2>(QuantityId::POSITION)[k][0], o + 2);
        EXPECT_EQ(s.getValue<double>(QuantityId::ENERGY)[k], o);
        EXPECT_EQ(s.getDt<double>(QuantityId::ENERGY)[k], o + 1);
        EXPECT_EQ(s.getValue<double>(MY_SCALAR)[k], o);
    }
}

TEST(Storage, InsertSetsCountKeepsValuesAndRaisesOrder) {
    Storage<2> s;
    s.insert<double>(QuantityId::MASS, OrderEnum::ZERO, std::vector<double>{1, 2, 3});
    EXPECT_EQ(s.size(), 3u);
    s.insert<double>(QuantityId::DENSITY, OrderEnum::ZERO, 1000.0);
    EXPECT_EQ(s.getValue<double>(QuantityId::DENSITY)[2], 1000.0);
    // Inserting again keeps the values and raises the order; new derivatives start at zero.
    s.insert<double>(QuantityId::MASS, OrderEnum::FIRST, 9.0);
    EXPECT_EQ(s.getValue<double>(QuantityId::MASS)[1], 2.0);
    EXPECT_EQ(s.order(QuantityId::MASS), OrderEnum::FIRST);
    EXPECT_EQ(s.getDt<double>(QuantityId::MASS)[1], 0.0);
    EXPECT_THROW(s.getD2t<double>(QuantityId::MASS), std::logic_error);
    EXPECT_THROW(s.insert<int>(QuantityId::MASS, OrderEnum::ZERO, 1), std::logic_error);
    EXPECT_THROW(s.getValue<V2>(QuantityId::MASS), std::logic_error);
    EXPECT_THROW(s.getValue<double>(QuantityId::PRESSURE), std::out_of_range);
    EXPECT_THROW(s.insert<double>(QuantityId::PRESSURE, OrderEnum::ZERO, std::vector<double>(2)),
                 std::invalid_argument);
}

TEST(Storage, UserQuantityIdsAndGetValues) {
    Storage<2> s = encoded(4);
    EXPECT_TRUE(s.has(MY_SCALAR));
    EXPECT_FALSE(s.has(QuantityId(AdditionalId(-8))));
    ArrayView<double> a, b;
    std::tie(a, b) = s.getValues<double>(QuantityId::ENERGY, MY_SCALAR);
    EXPECT_EQ(a[3], 300.0);
    EXPECT_EQ(b[3], 300.0);
}

TEST(Storage, ReorderKeepsEveryLevelConsistent) {
    Storage<2> s = encoded(5);
    s.reorder({3, 0, 4, 1, 2});
    expectParticles(s, {300, 0, 400, 100, 200});
    EXPECT_EQ(s.getValue<int>(QuantityId::KIND)[0], 3);
    EXPECT_THROW(s.reorder({0, 0, 1, 2, 3}), std::invalid_argument);
    EXPECT_THROW(s.reorder({0, 1}), std::invalid_argument);
}

TEST(Storage, RemoveKeepsTheOthersInOrder) {
    Storage<2> s = encoded(6);
    s.remove({4, 1, 4});
    expectParticles(s, {0, 200, 300, 500});
    EXPECT_THROW(s.remove({9}), std::out_of_range);
}

TEST(Storage, AppendAddsParticlesAndRenumbersMaterials) {
    auto water = std::make_shared<Material>("water");
    auto oil = std::make_shared<Material>("oil");
    Storage<2> a = encoded(2);
    a.insert<int>(QuantityId::MATERIAL, OrderEnum::ZERO, 0);
    a.materials() = {water};
    Storage<2> b = encoded(3, 0.5);
    b.insert<int>(QuantityId::MATERIAL, OrderEnum::ZERO, std::vector<int>{0, 1, 0});
    b.materials() = {oil, water};
    a.append(b);
    expectParticles(a, {0, 100, 0.5, 100.5, 200.5});
    ASSERT_EQ(a.materials().size(), 2u);
    const auto mat = a.getValue<int>(QuantityId::MATERIAL);
    EXPECT_EQ(a.materials()[mat[0]]->name(), "water");
    EXPECT_EQ(a.materials()[mat[2]]->name(), "oil");
    EXPECT_EQ(a.materials()[mat[3]]->name(), "water");
    EXPECT_EQ(a.materials()[mat[4]]->name(), "oil");

    Storage<2> missing;
    missing.insert<double>(QuantityId::MASS, OrderEnum::ZERO, std::vector<double>{1});
    EXPECT_THROW(a.append(missing), std::invalid_argument);
}

TEST(Storage, GatherCopiesAndDropsHaloParticles) {
    Storage<2> s = encoded(3);
    s.gather({2, 2, 0});  // e.g. halo copies
    expectParticles(s, {200, 200, 0});
    s.remove({0, 1});
    expectParticles(s, {0});
    EXPECT_THROW(s.gather({1}), std::out_of_range);
}

}  // namespace
