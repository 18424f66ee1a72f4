#include "graph/budget/RecursiveLeastSquares.hpp"
#include "graph/core/Check.hpp"

#include <cstdlib>

namespace arcomp {

RecursiveLeastSquares::RecursiveLeastSquares(std::size_t size, double forgetting, double initialVariance,
                                             double maxTrace)
    : n_(size), lambda_(forgetting), maxTrace_(maxTrace), theta_(size, 0.0), p_(size * size, 0.0), px_(size, 0.0) {
    ARCOMP_CHECK(size > 0 && forgetting > 0.0 && forgetting <= 1.0,
                 "a fit needs parameters and a forgetting factor in (0, 1]");
    for (std::size_t i = 0; i < n_; ++i) p_[i * n_ + i] = initialVariance;
}

void RecursiveLeastSquares::reset(std::span<const double> theta, std::span<const double> variances) {
    ARCOMP_CHECK(theta.size() == n_ && variances.size() == n_, "one estimate and one variance per parameter");
    theta_.assign(theta.begin(), theta.end());
    p_.assign(n_ * n_, 0.0);
    for (std::size_t i = 0; i < n_; ++i) p_[i * n_ + i] = variances[i];
    samples_ = 0;
}

void RecursiveLeastSquares::add(std::span<const double> x, double y) {
    ARCOMP_CHECK(x.size() == n_, "one regressor per parameter");
    // Gain k = P x / (λ + xᵀ P x); θ += k (y - θ·x); P = (P - k xᵀ P) / λ.
    double denominator = lambda_;
    for (std::size_t i = 0; i < n_; ++i) {
        double s = 0.0;
        for (std::size_t j = 0; j < n_; ++j) s += p_[i * n_ + j] * x[j];
        px_[i] = s;
        denominator += x[i] * s;
    }
    const double error = y - predict(x);
    for (std::size_t i = 0; i < n_; ++i) theta_[i] += px_[i] / denominator * error;
    // P is symmetric, so xᵀP = (Px)ᵀ.
    double trace = 0.0;
    for (std::size_t i = 0; i < n_; ++i)
        for (std::size_t j = 0; j < n_; ++j) {
            double& pij = p_[i * n_ + j];
            pij = (pij - px_[i] * px_[j] / denominator) / lambda_;
            if (i == j) trace += pij;
        }
    if (trace > maxTrace_)
        for (double& v : p_) v *= maxTrace_ / trace;
    ++samples_;
}

double RecursiveLeastSquares::predict(std::span<const double> x) const {
    double y = 0.0;
    for (std::size_t i = 0; i < n_; ++i) y += theta_[i] * x[i];
    return y;
}

}  // namespace arcomp
