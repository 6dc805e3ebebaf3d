// NumPy arrays over a run's particle storage, without copying. A view shows the run's own
// arrays until the next step; before that step its arrays are detached: the views keep the
// buffers they show (moved into their ViewKeeper) and the run goes on with copies, so a view
// kept across a step is a snapshot, never a dangling pointer.
#pragma once

#include <pybind11/numpy.h>

#include <memory>
#include <string>
#include <utility>
#include <vector>

#include "app/fields.hpp"
#include "bindings.hpp"
#include "sph/storage.hpp"

namespace num::python {

/// Owns what the views of one step show once they are detached; alive while any of them is
/// (each view's base).
class ViewKeeper {
  public:
    /// `owner`: the simulation, kept alive while its particles are shown.
    explicit ViewKeeper(py::object owner) : owner_(std::move(owner)) {}
    /// Records that a view shows level `level` (0: value, 1: dt) of quantity `id`.
    void shows(sph::QuantityId id, int level) { shown_.emplace_back(id, level); }
    /// Moves the buffers shown into this keeper and gives the storage copies (the GIL held).
    template <int Dim>
    void detach(sph::Storage<Dim>& s);

  private:
    py::object owner_;
    std::vector<std::pair<sph::QuantityId, int>> shown_;
    std::vector<std::shared_ptr<void>> held_;
};

/// The names of the fields a view can show: position, then the outputs' fields (velocity,
/// density, ..., id and every user or plugin quantity).
template <int Dim>
std::vector<std::string> particleFieldNames(const sph::Storage<Dim>& s,
                                            const app::FieldNames& names);

/// A view of field `name` (ValueError when the run has no such field); `keeper` is its base.
template <int Dim>
py::array particleView(sph::Storage<Dim>& s, const app::FieldNames& names, const std::string& name,
                       bool writable, const std::shared_ptr<ViewKeeper>& keeper);

void bindViewKeeper(py::module_& m);

}  // namespace num::python
