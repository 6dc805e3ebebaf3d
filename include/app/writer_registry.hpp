// The output formats by name: one table from which the scene's output.formats is checked, its
// error text lists the names, and Outputs<Dim> makes the writers. The built-in formats ("vtu",
// "csv") are in builtInWriters(); a plugin adds its own (app/plugin.hpp, addWriter).
#pragma once

#include <functional>
#include <memory>
#include <string>
#include <utility>
#include <vector>

#include "app/output_writer.hpp"

namespace num::app {

/// Makes a writer of dimension Dim for a run.
template <int Dim>
using WriterFactory = std::function<std::unique_ptr<IWriter<Dim>>(const WriterContext&)>;

/// The factory of Writer (derived from IWriter<Writer::dim>): Writer(context).
template <class Writer>
WriterFactory<Writer::dim> writerFactory() {
    return [](const WriterContext& context) -> std::unique_ptr<IWriter<Writer::dim>> {
        return std::make_unique<Writer>(context);
    };
}

/// Writers by name, for 2D and 3D (a name may have both), in the order they were added.
class WriterRegistry {
  public:
    /// Registers a writer; a name already taken for that dimension is a std::logic_error.
    void add(const std::string& name, WriterFactory<2> factory);
    void add(const std::string& name, WriterFactory<3> factory);
    /// Registers Writer<2> and Writer<3> (classes derived from IWriter<Dim>), each made by
    /// `Writer<Dim>(context)`.
    template <template <int> class Writer>
    void add(const std::string& name) {
        add(name, writerFactory<Writer<2>>());
        add(name, writerFactory<Writer<3>>());
    }

    template <int Dim>
    bool has(const std::string& name) const;
    /// The names of the writers of dimension Dim, in the order they were added.
    template <int Dim>
    std::vector<std::string> names() const;
    /// The writer `name` (registered for Dim) for a run.
    template <int Dim>
    std::unique_ptr<IWriter<Dim>> make(const std::string& name, const WriterContext& context) const;

  private:
    template <int Dim>
    const std::vector<std::pair<std::string, WriterFactory<Dim>>>& table() const;

    std::vector<std::pair<std::string, WriterFactory<2>>> writers2_;
    std::vector<std::pair<std::string, WriterFactory<3>>> writers3_;
};

/// The formats numerics ships ("vtu", "csv").
WriterRegistry builtInWriters();

/// Checks that every name of `formats` (the scene's output.formats, read from `file`) is a writer
/// of `writers` for Dim; else an AppError SCENE naming the file and the key, e.g.
/// "scene.json: output.formats.1: expected one of "vtu", "csv", found the string "vtk" (did you
/// mean "vtu"?)".
template <int Dim>
void checkOutputFormats(const std::string& file, const std::vector<std::string>& formats,
                        const WriterRegistry& writers);

}  // namespace num::app
