// The per-particle fields the writers put out: the standard ones (velocity, density, pressure,
// temperature, mass, material, kind, id) and every quantity a user term registered under its own id
// (negative or >= QuantityId::USER_FIRST), named through FieldNames or "user_<id>".
#pragma once

#include <map>
#include <set>
#include <string>
#include <vector>

#include "sph/storage.hpp"

namespace num::app {

using sph::QuantityId;

struct OutputField {
    enum class Type { FLOAT, VECTOR, INT };
    std::string name;
    QuantityId id;
    Type type;
    bool derivative = false;  ///< the dt level (velocity is the dt of POSITION)
};

/// Names of quantities for output; users add theirs with add().
class FieldNames {
  public:
    FieldNames& add(QuantityId id, std::string name) {
        names_[id] = std::move(name);
        return *this;
    }
    /// The registered name, or "" when none.
    std::string name(QuantityId id) const {
        auto it = names_.find(id);
        return it == names_.end() ? "" : it->second;
    }
    const std::map<QuantityId, std::string>& all() const { return names_; }
    /// Leaves a quantity out of the outputs (a plugin's quantity the scene does not name).
    FieldNames& hide(QuantityId id) {
        hidden_.insert(id);
        return *this;
    }
    bool hidden(QuantityId id) const { return hidden_.count(id) != 0; }

  private:
    std::map<QuantityId, std::string> names_;
    std::set<QuantityId> hidden_;
};

/// The fields of the storage to write, standard ones first, in a fixed order.
template <int Dim>
std::vector<OutputField> outputFields(const sph::Storage<Dim>& s, const FieldNames& names = {}) {
    using T = OutputField::Type;
    std::vector<OutputField> out;
    if (s.has(QuantityId::POSITION) && int(s.order(QuantityId::POSITION)) >= 1)
        out.push_back({"velocity", QuantityId::POSITION, T::VECTOR, true});
    const std::pair<QuantityId, const char*> standard[] = {
        {QuantityId::DENSITY, "density"},         {QuantityId::PRESSURE, "pressure"},
        {QuantityId::TEMPERATURE, "temperature"}, {QuantityId::MASS, "mass"},
        {QuantityId::MATERIAL, "material"},       {QuantityId::KIND, "kind"},
        {QuantityId::PARTICLE_ID, "id"}};
    auto typeOf = [&](QuantityId id) {
        const auto& q = s.get(id);
        return q.template holds<sph::Float>() ? T::FLOAT
               : q.template holds<int>()      ? T::INT
                                              : T::VECTOR;
    };
    for (const auto& [id, name] : standard)
        if (s.has(id)) out.push_back({name, id, typeOf(id)});
    s.forEach([&](QuantityId id, const auto&) {
        const bool user = int(id) < 0 || int(id) >= int(QuantityId::USER_FIRST);
        if (names.hidden(id)) return;
        std::string name = names.name(id);
        if (!user && name.empty()) return;
        for (const auto& f : out)
            if (f.id == id && !f.derivative) return;
        if (name.empty()) name = "user_" + std::to_string(int(id));
        out.push_back({name, id, typeOf(id)});
    });
    return out;
}

}  // namespace num::app
