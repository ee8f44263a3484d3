// Logistic regression of a binary outcome on two inputs with polynomial features, as the thesis
// uses to find a bonding boundary from a grid of calibration impacts (mpm-bonding-thesis.md
// §4.1.2, eqs 4.10-4.14; §5.1.1). Pure math: no dependence on the MPM code. See
// docs/studies-math.md.
//
// The model is h = sigma(Z), Z = theta . X(u1, u2), where X holds the monomials of total degree
// <= `degree` of the *scaled* inputs u (degree 2 gives the thesis' [1, u1, u2, u1^2, u1 u2, u2^2],
// eq 4.12). Each input x_k is first transformed, t_k = x_k or log10 x_k, then, by default,
// standardised, u_k = (t_k - mean_k) / std_k over the training samples. Scaling matters: the
// thesis' inputs G_c ~ 1e2-5e3 J/m^2 and Gdot_c ~ 1e5-1e8 J/m^2/s give raw quadratic features
// spanning 1e0-1e16, which no optimiser handles well, and a ridge term is only meaningful when
// the features have comparable sizes. z(), probability() and predict() take raw inputs and apply
// the same scaling, so callers never see u.
#pragma once

#include <Eigen/Core>
#include <array>
#include <vector>

namespace coldspray::studies {

// One labelled run: inputs (x1, x2) and outcome y (1 bonded, 0 not; thesis eqs 4.8-4.9).
struct Sample {
  double x1 = 0.0;
  double x2 = 0.0;
  int y = 0;
};

// The transform applied to an input before standardisation. Log10 needs x > 0; use it for an
// input spanning orders of magnitude (e.g. Gdot_c), so that the boundary is smooth in it.
enum class InputTransform { Identity, Log10 };

struct LogisticOptions {
  int degree = 2;  // total degree of the polynomial features: 2 is eq 4.11; 1 to 4 allowed
  std::array<InputTransform, 2> transform = {InputTransform::Identity, InputTransform::Identity};
  bool standardize =
      true;  // u = (t - mean) / std over the samples (std = 1 if an input is constant)
  // lambda of the ridge term (lambda / 2m) |theta|^2 added to the mean cross-entropy, on all
  // coefficients but the intercept theta_1. Keeps theta finite for separable data; > 0 advised.
  double ridge = 1e-3;
  int max_iterations = 200;          // Newton iterations
  double gradient_tolerance = 1e-9;  // stop when |grad J|_2 <= this (scaled-feature space)
};

// The transform and standardisation of the two inputs, fixed at fit time.
struct InputScaling {
  std::array<InputTransform, 2> transform = {InputTransform::Identity, InputTransform::Identity};
  Eigen::Vector2d mean = Eigen::Vector2d::Zero();   // of t, over the training samples
  Eigen::Vector2d scale = Eigen::Vector2d::Ones();  // std of t (1 when not standardising)

  // t = transform(x); throws std::domain_error for log10 of x <= 0.
  Eigen::Vector2d transformed(double x1, double x2) const;
  // u = (t - mean) / scale.
  Eigen::Vector2d scaled(double x1, double x2) const;
};

// The monomials of total degree <= `degree` in (u1, u2), ordered by degree and then by falling
// power of u1: 1, u1, u2, u1^2, u1 u2, u2^2, u1^3, ... (eq 4.12 for degree 2).
Eigen::VectorXd polynomial_features(double u1, double u2, int degree);
int feature_count(int degree);  // (degree + 1)(degree + 2) / 2

// Numerically safe sigma(z) = 1 / (1 + e^-z) (eq 4.10).
double sigmoid(double z);

struct LogisticFit {
  Eigen::VectorXd theta;  // coefficients of polynomial_features(u1, u2, degree), u scaled
  int degree = 2;
  InputScaling scaling;
  int iterations = 0;      // Newton iterations taken
  bool converged = false;  // gradient norm reached the tolerance
  double cost = 0.0;       // J(theta) (eq 4.13) plus the ridge term, at theta
  double gradient_norm = 0.0;
  double accuracy = 0.0;  // fraction of training samples with (Z >= 0) == (y == 1)
  std::size_t samples = 0;

  double z(double x1, double x2) const;            // Z at raw inputs (eq 4.11)
  double probability(double x1, double x2) const;  // h(Z) (eq 4.10)
  int predict(double x1, double x2) const;         // 1 when Z >= 0 (h >= 0.5), else 0
  // The same polynomial written in the transformed but unstandardised inputs t (t = x for
  // Identity): Z = theta_t . polynomial_features(t1, t2). With Identity transforms this is the
  // thesis' theta of eq 4.12 in the inputs' own units (badly conditioned to evaluate when the
  // inputs are large; prefer z()).
  Eigen::VectorXd theta_unstandardized() const;
};

// Minimises J(theta) + (lambda / 2m) sum_{j>1} theta_j^2 (eq 4.13 plus ridge) by Newton's method
// (iteratively reweighted least squares): gradient eq 4.14 plus the ridge part, Hessian
// (1/m) X^T W X + (lambda/m) R with W = h(1-h), solved by LDLT; a step is halved while it raises
// the cost. Throws std::invalid_argument for no samples, a label other than 0/1, only one class
// present, bad options, or non-finite inputs.
LogisticFit fit_logistic(const std::vector<Sample>& samples, const LogisticOptions& options = {});

}  // namespace coldspray::studies
