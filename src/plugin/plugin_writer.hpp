// A plugin's writer as the run sees it (internal to numerics_app): every hook runs guarded, so an
// exception from plugin code becomes an AppError (exit code PLUGIN) that names the writer, the
// hook and the time; AppErrors (e.g. a full disk, exit code OUTPUT) pass unchanged.
#pragma once

#include <exception>
#include <memory>
#include <string>
#include <utility>

#include "app/errors.hpp"
#include "app/formatted.hpp"
#include "app/writer_registry.hpp"

namespace num::app {

template <int Dim>
class PluginWriter final : public IWriter<Dim> {
  public:
    /// `label` names the writer in messages, e.g. `writer "xyz" (libxyz.so)`.
    PluginWriter(const WriterFactory<Dim>& factory, const WriterContext& context, std::string label)
        : label_(std::move(label)) {
        guard("its factory", -1, [&] { writer_ = factory(context); });
        if (!writer_) throw AppError(ExitCode::PLUGIN, label_ + ": its factory returned no writer");
    }

    void start() override {
        guard("start", -1, [&] { writer_->start(); });
    }
    void resume(double t, const OutputSeries& series) override {
        guard("resume", t, [&] { writer_->resume(t, series); });
    }
    void write(const sph::Storage<Dim>& s, const std::vector<OutputField>& fields, double t,
               int index) override {
        guard("write", t, [&] { writer_->write(s, fields, t, index); });
    }
    void finish(bool completed, EndOfRun& end) override {
        guard("finish", -1, [&] { writer_->finish(completed, end); });
    }
    std::vector<WrittenFile> files() const override {
        std::vector<WrittenFile> out;
        guard("files", -1, [&] { out = writer_->files(); });
        return out;
    }
    const PvdSeries* series() const override {
        const PvdSeries* out = nullptr;
        guard("series", -1, [&] { out = writer_->series(); });
        return out;
    }

  private:
    template <class F>
    void guard(const char* hook, double t, F&& f) const {
        try {
            f();
        } catch (const AppError&) {
            throw;
        } catch (const std::exception& e) {
            throw AppError(ExitCode::PLUGIN, where(hook, t) + ": " + e.what());
        } catch (...) {
            throw AppError(ExitCode::PLUGIN,
                           where(hook, t) + ": it threw something that is not a std::exception");
        }
    }
    std::string where(const char* hook, double t) const {
        std::string text = label_ + " failed in " + hook;
        if (t >= 0) text += formatted(" at t = %.6g s", t);
        return text;
    }

    std::unique_ptr<IWriter<Dim>> writer_;
    std::string label_;
};

/// The factory of `factory`'s writers, each guarded (PluginWriter) under `label`.
template <int Dim>
WriterFactory<Dim> guardedWriterFactory(WriterFactory<Dim> factory, std::string label) {
    return [factory = std::move(factory), label = std::move(label)](
               const WriterContext& context) -> std::unique_ptr<IWriter<Dim>> {
        return std::make_unique<PluginWriter<Dim>>(factory, context, label);
    };
}

}  // namespace num::app
