// A plugin's term as the run sees it (internal to numerics_io): every hook of the term runs
// guarded, so an exception from plugin code becomes an AppError (exit code PLUGIN) that names
// the term, the hook and the time, and the run stops with its last good output.
#pragma once

#include <exception>
#include <memory>
#include <string>
#include <utility>

#include "io/errors.hpp"
#include "io/formatted.hpp"
#include "sph/equation_term.hpp"

namespace num::io {

template <int Dim>
class PluginTerm final : public sph::IEquationTerm<Dim> {
  public:
    /// `label` names the term in messages, e.g. `term "spring" (plugins.0.terms.1, libx.so)`.
    PluginTerm(std::shared_ptr<sph::IEquationTerm<Dim>> term, std::string label)
        : term_(std::move(term)), label_(std::move(label)) {}

    void setDerivatives(sph::DerivativeHolder<Dim>& d, const sph::RunSettings& s) override {
        guard("setDerivatives", -1, [&] { term_->setDerivatives(d, s); });
    }
    void beginEvaluation(const sph::EvaluationContext<Dim>& context) override {
        guard("beginEvaluation", -1, [&] { term_->beginEvaluation(context); });
    }
    void initialize(sph::IScheduler& sch, sph::Storage<Dim>& s, sph::Float t) override {
        guard("initialize", t, [&] { term_->initialize(sch, s, t); });
    }
    void finalize(sph::IScheduler& sch, sph::Storage<Dim>& s, sph::Float t) override {
        guard("finalize", t, [&] { term_->finalize(sch, s, t); });
    }
    void postStep(sph::IScheduler& sch, sph::Storage<Dim>& s, sph::Float t,
                  sph::Float dt) override {
        guard("postStep", t, [&] { term_->postStep(sch, s, t, dt); });
    }
    void create(sph::Storage<Dim>& s, sph::IMaterial& m) const override {
        guard("create", -1, [&] { term_->create(s, m); });
    }
    void limitTimeStep(const sph::Storage<Dim>& s, const sph::RunSettings& rs,
                       sph::TimeStepLimits& l) const override {
        guard("limitTimeStep", -1, [&] { term_->limitTimeStep(s, rs, l); });
    }

    sph::TermAccess access() const override {
        sph::TermAccess result;
        guard("access", -1, [&] { result = term_->access(); });
        return result;
    }

    std::string name() const override { return label_; }

  private:
    /// Runs f; an exception from it becomes an AppError naming the term and the hook (and the
    /// time t when t >= 0). AppErrors (e.g. an instability found by the term) pass unchanged.
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

    std::shared_ptr<sph::IEquationTerm<Dim>> term_;
    std::string label_;
};

}  // namespace num::io
