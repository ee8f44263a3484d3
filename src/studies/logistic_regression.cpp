#include "studies/logistic_regression.hpp"

#include <Eigen/Cholesky>
#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <string>

namespace coldspray::studies {

namespace {

// log(1 + e^z) without overflow.
double softplus(double z) {
  return z > 0.0 ? z + std::log1p(std::exp(-z)) : std::log1p(std::exp(z));
}

double binomial(int n, int k) {
  double c = 1.0;
  for (int i = 1; i <= k; ++i) c = c * (n - k + i) / i;
  return c;
}

// The design matrix of the samples in scaled inputs: one row of features per sample.
Eigen::MatrixXd design_matrix(const std::vector<Sample>& samples, const InputScaling& scaling,
                              int degree) {
  Eigen::MatrixXd X(static_cast<Eigen::Index>(samples.size()), feature_count(degree));
  for (std::size_t i = 0; i < samples.size(); ++i) {
    const Eigen::Vector2d u = scaling.scaled(samples[i].x1, samples[i].x2);
    X.row(static_cast<Eigen::Index>(i)) = polynomial_features(u(0), u(1), degree).transpose();
  }
  return X;
}

// The mean cross-entropy (eq 4.13) written as mean(softplus(Z) - y Z), which is the same for
// y in {0, 1} and never takes the log of 0, plus the ridge term (lambda / 2m) sum_{j>1} theta_j^2.
double penalised_cost(const Eigen::VectorXd& Z, const Eigen::VectorXd& y,
                      const Eigen::VectorXd& theta, double lambda) {
  const double m = static_cast<double>(Z.size());
  double sum = 0.0;
  for (Eigen::Index i = 0; i < Z.size(); ++i) sum += softplus(Z(i)) - y(i) * Z(i);
  return sum / m + lambda / (2.0 * m) * theta.tail(theta.size() - 1).squaredNorm();
}

void check_options(const LogisticOptions& o) {
  if (o.degree < 1 || o.degree > 4)
    throw std::invalid_argument("logistic regression: degree must be 1 to 4, got " +
                                std::to_string(o.degree));
  if (!(o.ridge >= 0.0) || !std::isfinite(o.ridge))
    throw std::invalid_argument("logistic regression: ridge must be finite and >= 0");
  if (o.max_iterations < 1)
    throw std::invalid_argument("logistic regression: max_iterations must be >= 1");
  if (!(o.gradient_tolerance > 0.0))
    throw std::invalid_argument("logistic regression: gradient_tolerance must be > 0");
}

// Fixes the transform from the options and, when standardising, the mean and (population)
// standard deviation of each transformed input over the samples.
InputScaling fit_scaling(const std::vector<Sample>& samples, const LogisticOptions& o) {
  InputScaling s;
  s.transform = o.transform;
  if (!o.standardize) return s;
  Eigen::Vector2d sum = Eigen::Vector2d::Zero();
  for (const Sample& p : samples) sum += s.transformed(p.x1, p.x2);
  const double m = static_cast<double>(samples.size());
  s.mean = sum / m;
  Eigen::Vector2d var = Eigen::Vector2d::Zero();
  for (const Sample& p : samples)
    var += (s.transformed(p.x1, p.x2) - s.mean).array().square().matrix();
  for (int k = 0; k < 2; ++k) {
    const double sd = std::sqrt(var(k) / m);
    s.scale(k) = sd > 0.0 ? sd : 1.0;
  }
  return s;
}

}  // namespace

Eigen::Vector2d InputScaling::transformed(double x1, double x2) const {
  Eigen::Vector2d t(x1, x2);
  for (int k = 0; k < 2; ++k) {
    if (transform[k] != InputTransform::Log10) continue;
    if (!(t(k) > 0.0))
      throw std::domain_error("logistic regression: input x" + std::to_string(k + 1) +
                              " must be > 0 for a log10 transform, got " + std::to_string(t(k)));
    t(k) = std::log10(t(k));
  }
  return t;
}

Eigen::Vector2d InputScaling::scaled(double x1, double x2) const {
  return ((transformed(x1, x2) - mean).array() / scale.array()).matrix();
}

int feature_count(int degree) { return (degree + 1) * (degree + 2) / 2; }

Eigen::VectorXd polynomial_features(double u1, double u2, int degree) {
  Eigen::VectorXd f(feature_count(degree));
  Eigen::Index j = 0;
  for (int total = 0; total <= degree; ++total)
    for (int p2 = 0; p2 <= total; ++p2) f(j++) = std::pow(u1, total - p2) * std::pow(u2, p2);
  return f;
}

double sigmoid(double z) {
  if (z >= 0.0) return 1.0 / (1.0 + std::exp(-z));
  const double e = std::exp(z);
  return e / (1.0 + e);
}

double LogisticFit::z(double x1, double x2) const {
  const Eigen::Vector2d u = scaling.scaled(x1, x2);
  return theta.dot(polynomial_features(u(0), u(1), degree));
}

double LogisticFit::probability(double x1, double x2) const { return sigmoid(z(x1, x2)); }

int LogisticFit::predict(double x1, double x2) const { return z(x1, x2) >= 0.0 ? 1 : 0; }

// Each scaled monomial u1^a u2^b = ((t1 - m1)/s1)^a ((t2 - m2)/s2)^b expands binomially into
// monomials t1^i t2^j (i <= a, j <= b) of the same or lower degree.
Eigen::VectorXd LogisticFit::theta_unstandardized() const {
  const int n = feature_count(degree);
  auto index = [](int p1, int p2) { return feature_count(p1 + p2 - 1) + p2; };
  Eigen::VectorXd out = Eigen::VectorXd::Zero(n);
  const double m1 = scaling.mean(0), m2 = scaling.mean(1);
  const double s1 = scaling.scale(0), s2 = scaling.scale(1);
  for (int total = 0; total <= degree; ++total) {
    for (int b = 0; b <= total; ++b) {
      const int a = total - b;
      const double c = theta(index(a, b)) / (std::pow(s1, a) * std::pow(s2, b));
      for (int i = 0; i <= a; ++i)
        for (int j = 0; j <= b; ++j)
          out(index(i, j)) +=
              c * binomial(a, i) * std::pow(-m1, a - i) * binomial(b, j) * std::pow(-m2, b - j);
    }
  }
  return out;
}

namespace {

// Labels 0 or 1, finite inputs, and both classes present: else there is no boundary to fit.
void check_samples(const std::vector<Sample>& samples) {
  if (samples.empty()) throw std::invalid_argument("logistic regression: no samples");
  std::size_t positives = 0;
  for (const Sample& s : samples) {
    if (s.y != 0 && s.y != 1)
      throw std::invalid_argument("logistic regression: labels must be 0 or 1, got " +
                                  std::to_string(s.y));
    if (!std::isfinite(s.x1) || !std::isfinite(s.x2))
      throw std::invalid_argument("logistic regression: non-finite input");
    positives += static_cast<std::size_t>(s.y);
  }
  if (positives == 0 || positives == samples.size())
    throw std::invalid_argument(
        "logistic regression: the samples hold only one class; there is no boundary to fit");
}

// The penalised problem: design matrix X, labels y, ridge lambda with R = diag(0, 1, ..., 1)
// (the ridge leaves the intercept free).
struct RidgeProblem {
  const Eigen::MatrixXd& X;
  Eigen::VectorXd y;
  Eigen::VectorXd R;
  double lambda;
  double m;

  // The hypothesis h = sigmoid(Z) and, into grad, eq 4.14 plus the ridge part (lambda/m) R theta.
  Eigen::VectorXd gradient(const Eigen::VectorXd& Z, const Eigen::VectorXd& theta,
                           Eigen::VectorXd& grad) const {
    Eigen::VectorXd h = Z.unaryExpr([](double v) { return sigmoid(v); });
    grad = X.transpose() * (h - y) / m + (lambda / m) * R.cwiseProduct(theta);
    return h;
  }

  // The Newton step on the Hessian (1/m) X^T W X + (lambda/m) R, W = diag(h (1 - h)). If the
  // Hessian is numerically singular (no ridge and separated data, w ~ 0), a Levenberg term is
  // added until LDLT gives a descent direction; steepest descent is the last resort.
  Eigen::VectorXd newton_step(const Eigen::VectorXd& h, const Eigen::VectorXd& grad) const {
    const Eigen::VectorXd w = h.cwiseProduct(Eigen::VectorXd::Ones(h.size()) - h);
    Eigen::MatrixXd H = X.transpose() * w.asDiagonal() * X / m;
    H.diagonal() += (lambda / m) * R;
    Eigen::VectorXd step;
    double damping = 0.0;
    const double base = std::max(H.diagonal().maxCoeff(), 1e-300);
    for (int attempt = 0; attempt < 20; ++attempt) {
      Eigen::MatrixXd Hd = H;
      Hd.diagonal().array() += damping;
      Eigen::LDLT<Eigen::MatrixXd> ldlt(Hd);
      if (ldlt.info() == Eigen::Success && ldlt.isPositive()) {
        step = -ldlt.solve(grad);
        if (step.allFinite() && step.dot(grad) < 0.0) return step;
      }
      damping = damping == 0.0 ? 1e-10 * base : 10.0 * damping;
    }
    return -grad;
  }

  // Step halving: accept the first fraction of the step that does not raise the cost. Near the
  // optimum a Newton step lowers the cost by less than its rounding error (~1e-16), so a rise
  // within `slack` still counts as no rise; otherwise the last digits would stall the descent.
  // False when no decrease is possible at machine precision.
  bool descend(const Eigen::VectorXd& step, Eigen::VectorXd& theta, Eigen::VectorXd& Z,
               double& cost) const {
    const double slack = 1e-13 * std::max(1.0, std::abs(cost));
    double t = 1.0;
    for (int halving = 0; halving < 50; ++halving, t *= 0.5) {
      const Eigen::VectorXd trial = theta + t * step;
      const Eigen::VectorXd Zt = X * trial;
      const double ct = penalised_cost(Zt, y, trial, lambda);
      if (ct <= cost + slack) {
        theta = trial;
        Z = Zt;
        cost = ct;
        return true;
      }
    }
    return false;
  }
};

}  // namespace

LogisticFit fit_logistic(const std::vector<Sample>& samples, const LogisticOptions& options) {
  check_options(options);
  check_samples(samples);
  LogisticFit fit;
  fit.degree = options.degree;
  fit.samples = samples.size();
  fit.scaling = fit_scaling(samples, options);
  const Eigen::MatrixXd X = design_matrix(samples, fit.scaling, options.degree);
  RidgeProblem p{X, Eigen::VectorXd(X.rows()), Eigen::VectorXd::Ones(X.cols()), options.ridge,
                 static_cast<double>(X.rows())};
  for (Eigen::Index i = 0; i < X.rows(); ++i) p.y(i) = samples[static_cast<std::size_t>(i)].y;
  p.R(0) = 0.0;

  Eigen::VectorXd theta = Eigen::VectorXd::Zero(X.cols());
  Eigen::VectorXd Z = X * theta;
  double cost = penalised_cost(Z, p.y, theta, p.lambda);
  Eigen::VectorXd grad(X.cols());
  Eigen::VectorXd h = p.gradient(Z, theta, grad);
  int iteration = 0;
  while (grad.norm() > options.gradient_tolerance && iteration < options.max_iterations) {
    ++iteration;
    if (!p.descend(p.newton_step(h, grad), theta, Z, cost)) break;
    h = p.gradient(Z, theta, grad);
  }

  fit.theta = theta;
  fit.iterations = iteration;
  fit.cost = cost;
  fit.gradient_norm = grad.norm();
  fit.converged = fit.gradient_norm <= options.gradient_tolerance;
  std::size_t correct = 0;
  for (Eigen::Index i = 0; i < Z.size(); ++i)
    if ((Z(i) >= 0.0) == (p.y(i) == 1.0)) ++correct;
  fit.accuracy = static_cast<double>(correct) / p.m;
  return fit;
}

}  // namespace coldspray::studies
