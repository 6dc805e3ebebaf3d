// NumPy views of a run's particles and the keeper of their buffers (particle_views.hpp).
#include <algorithm>
#include <optional>

#include "particle_views.hpp"

namespace num::python {

namespace {

using app::OutputField;
using sph::QuantityId;

/// Where a field lives in the storage.
struct FieldRef {
    QuantityId id;
    int level;  ///< 0: the value, 1: its dt (velocity)
    OutputField::Type type;
};

template <int Dim>
std::optional<FieldRef> findField(const sph::Storage<Dim>& s, const app::FieldNames& names,
                                  const std::string& name) {
    if (name == "position" && s.has(QuantityId::POSITION))
        return FieldRef{QuantityId::POSITION, 0, OutputField::Type::VECTOR};
    for (const OutputField& f : app::outputFields(s, names))
        if (f.name == name) return FieldRef{f.id, f.derivative ? 1 : 0, f.type};
    return std::nullopt;
}

/// The array over `v`: (n, Dim) for vectors, (n,) otherwise; read-only unless `writable`.
template <class T>
py::array arrayOver(std::vector<T>& v, bool writable, const py::object& base) {
    using Component = std::conditional_t<std::is_same_v<T, int>, int, double>;
    constexpr std::size_t components = sizeof(T) / sizeof(Component);
    std::vector<py::ssize_t> shape{py::ssize_t(v.size())}, strides{py::ssize_t(sizeof(T))};
    if (components > 1) shape.push_back(components), strides.push_back(sizeof(Component));
    if (v.empty()) return py::array_t<Component>(shape);
    py::array a(py::dtype::of<Component>(), shape, strides, reinterpret_cast<Component*>(v.data()),
                base);
    if (!writable)
        py::detail::array_proxy(a.ptr())->flags &= ~py::detail::npy_api::NPY_ARRAY_WRITEABLE_;
    return a;
}

}  // namespace

template <int Dim>
void ViewKeeper::detach(sph::Storage<Dim>& s) {
    std::sort(shown_.begin(), shown_.end());
    shown_.erase(std::unique(shown_.begin(), shown_.end()), shown_.end());
    for (const auto& [id, level] : shown_) {
        if (!s.has(id)) continue;
        s.get(id).visit([&, level = level](auto& b) {
            auto& v = b.level(level);
            auto copy = v;
            held_.push_back(std::make_shared<std::decay_t<decltype(v)>>(std::move(v)));
            v = std::move(copy);
        });
    }
    shown_.clear();
    owner_ = py::none();  // the snapshot needs the run no more
}

template <int Dim>
std::vector<std::string> particleFieldNames(const sph::Storage<Dim>& s,
                                            const app::FieldNames& names) {
    std::vector<std::string> out;
    if (s.has(QuantityId::POSITION)) out.push_back("position");
    for (const OutputField& f : app::outputFields(s, names)) out.push_back(f.name);
    return out;
}

template <int Dim>
py::array particleView(sph::Storage<Dim>& s, const app::FieldNames& names, const std::string& name,
                       bool writable, const std::shared_ptr<ViewKeeper>& keeper) {
    const std::optional<FieldRef> f = findField(s, names, name);
    if (!f) {
        std::string known;
        for (const std::string& n : particleFieldNames(s, names))
            known += (known.empty() ? "" : ", ") + n;
        throw py::value_error("particles: no field \"" + name +
                              "\" in this run (its fields: " + known + ")");
    }
    keeper->shows(f->id, f->level);
    const py::object base = py::cast(keeper);
    auto& q = s.get(f->id);
    if (f->type == OutputField::Type::VECTOR)
        return arrayOver(q.template buffers<sph::Vector<Dim>>().level(f->level), writable, base);
    if (f->type == OutputField::Type::INT)
        return arrayOver(q.template buffers<int>().level(f->level), writable, base);
    return arrayOver(q.template buffers<sph::Float>().level(f->level), writable, base);
}

void bindViewKeeper(py::module_& m) {
    py::class_<ViewKeeper, std::shared_ptr<ViewKeeper>>(
        m, "ViewKeeper", "Keeps the particle arrays that NumPy views show");
}

template void ViewKeeper::detach(sph::Storage<2>&);
template void ViewKeeper::detach(sph::Storage<3>&);
template std::vector<std::string> particleFieldNames(const sph::Storage<2>&,
                                                     const app::FieldNames&);
template std::vector<std::string> particleFieldNames(const sph::Storage<3>&,
                                                     const app::FieldNames&);
template py::array particleView(sph::Storage<2>&, const app::FieldNames&, const std::string&, bool,
                                const std::shared_ptr<ViewKeeper>&);
template py::array particleView(sph::Storage<3>&, const app::FieldNames&, const std::string&, bool,
                                const std::shared_ptr<ViewKeeper>&);

}  // namespace num::python
