#pragma once
// Recursive least squares with exponential forgetting: fits y ≈ θ·x one
// sample at a time, old samples weighing λ^age. The frame-time cost model
// uses it to follow the machine as its load changes (the uniform-frame-time
// paper's first open item).
//
//   RecursiveLeastSquares rls(2, 0.98);          // θ = (A, B), λ = 0.98
//   const double x[] = {pixels, 1.0};
//   rls.add(x, measuredMs);
//   double a = rls.parameters()[0];
//
// Forgetting lets the covariance grow in directions the data no longer
// excites (windup): a controller that holds the frame time steady feeds
// nearly the same x every frame. The covariance's trace is therefore capped,
// so the fit stays calm instead of jumping on the next unusual sample.

#include <span>
#include <vector>

namespace arcomp {

class RecursiveLeastSquares {
public:
    // `initialVariance` is the prior's variance per parameter (large: trust
    // the data at once); `maxTrace` caps the covariance's trace.
    RecursiveLeastSquares(std::size_t size, double forgetting, double initialVariance = 1e6, double maxTrace = 1e8);

    // Starts again from `theta`, with prior variance variances[i] for θ[i].
    void reset(std::span<const double> theta, std::span<const double> variances);
    void add(std::span<const double> x, double y);
    double predict(std::span<const double> x) const;

    std::span<const double> parameters() const { return theta_; }
    std::size_t samples() const { return samples_; }
    double forgetting() const { return lambda_; }

private:
    std::size_t n_;
    double lambda_;
    double maxTrace_;
    std::vector<double> theta_;
    std::vector<double> p_;  // n × n covariance, row-major
    std::vector<double> px_;
    std::size_t samples_ = 0;
};

}  // namespace arcomp
