#include "app/expression.hpp"

#include <muParser.h>

namespace num::app {

struct Expression::Impl {
    mu::Parser parser;
    double x = 0, y = 0, z = 0, t = 0;
    std::string text;
    bool usesTime = false;
    std::string variables;  ///< the variables the text uses, of "xyzt", in that order
};

Expression Expression::parse(const std::string& text) {
    auto impl = std::make_shared<Impl>();
    impl->text = text;
    try {
        impl->parser.DefineVar("x", &impl->x);
        impl->parser.DefineVar("y", &impl->y);
        impl->parser.DefineVar("z", &impl->z);
        impl->parser.DefineVar("t", &impl->t);
        impl->parser.SetExpr(text);
        impl->parser.Eval();  // parses now, so errors surface when the scene is read
        const auto used = impl->parser.GetUsedVar();
        impl->usesTime = used.count("t") != 0;
        for (const char* v : {"x", "y", "z", "t"})
            if (used.count(v)) impl->variables += v;
    } catch (const mu::Parser::exception_type& e) {
        std::string msg = e.GetMsg();
        while (!msg.empty() && (msg.back() == '.' || msg.back() == ' ')) msg.pop_back();
        throw ExpressionError(msg + " at character " + std::to_string(e.GetPos() + 1));
    }
    Expression ex;
    ex.impl_ = std::move(impl);
    return ex;
}

double Expression::operator()(double x, double y, double z, double t) const {
    if (!impl_) return constant_;
    impl_->x = x, impl_->y = y, impl_->z = z, impl_->t = t;
    try {
        return impl_->parser.Eval();
    } catch (const mu::Parser::exception_type& e) {
        throw ExpressionError("'" + impl_->text + "': " + e.GetMsg());
    }
}

bool Expression::dependsOnTime() const { return impl_ && impl_->usesTime; }

std::string Expression::variables() const { return impl_ ? impl_->variables : std::string(); }

const std::string& Expression::text() const {
    static const std::string empty;
    return impl_ ? impl_->text : empty;
}

}  // namespace num::app
