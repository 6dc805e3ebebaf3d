// A plugin's term as the run sees it (internal to numerics_app): every hook of the term runs
// guarded, so an exception from plugin code becomes an AppError (exit code PLUGIN) that names
// the term, the hook and the time, and the run stops with its last good output.
#pragma once

#include <exception>
#include <memory>
#include <optional>
#include <string>
#include <utility>

#include "app/errors.hpp"
#include "app/formatted.hpp"
#include "sph/equation_term.hpp"

namespace num::app {

/// The first failure of a plugin's term in a step. On several processes it is kept until the
/// step ends (a process that left mid-step would leave the others waiting in an exchange): the
/// plugins' hooks are skipped for the rest of the step, and the processes agree on the failure
/// at its end (Simulation), so that it is reported once.
struct PluginFailure {
    bool keepUntilStepEnd = false;
    std::optional<AppError> pending;

    /// Throws the pending failure, if any.
    void rethrow() {
        if (!pending) return;
        const AppError e = *pending;
        pending.reset();
        throw e;
    }
};

template <int Dim>
class PluginTerm final : public sph::IEquationTerm<Dim> {
  public:
    /// `label` names the term in messages, e.g. `term "spring" (plugins.0.terms.1, libx.so)`.
    PluginTerm(std::shared_ptr<sph::IEquationTerm<Dim>> term, std::string label,
               std::shared_ptr<PluginFailure> failure)
        : term_(std::move(term)), label_(std::move(label)), failure_(std::move(failure)) {}

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
    /// The error is thrown, or kept in `failure_` until the step ends.
    template <class F>
    void guard(const char* hook, double t, F&& f) const {
        if (failure_->pending) return;
        try {
            f();
        } catch (const AppError& e) {
            fail(e);
        } catch (const std::exception& e) {
            fail(AppError(ExitCode::PLUGIN, where(hook, t) + ": " + e.what()));
        } catch (...) {
            fail(AppError(ExitCode::PLUGIN,
                          where(hook, t) + ": it threw something that is not a std::exception"));
        }
    }
    void fail(const AppError& e) const {
        if (!failure_->keepUntilStepEnd) throw e;
        failure_->pending = e;
    }
    std::string where(const char* hook, double t) const {
        std::string text = label_ + " failed in " + hook;
        if (t >= 0) text += formatted(" at t = %.6g s", t);
        return text;
    }

    std::shared_ptr<sph::IEquationTerm<Dim>> term_;
    std::string label_;
    std::shared_ptr<PluginFailure> failure_;
};

}  // namespace num::app
