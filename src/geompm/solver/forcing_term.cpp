#include "geompm/solver/forcing_term.hpp"

#include <algorithm>
#include <cmath>

namespace geompm {

double forcing_term(const ForcingSettings& settings, const std::vector<double>& residuals,
                    double previous, double residual_tolerance) {
  if (!settings.enabled || residuals.empty()) return settings.floor;
  const double r = residuals.back();
  // A step's first correction carries its whole increment: solved tightly (eq. 4.12a).
  double eta = residuals.size() == 1 ? settings.first : settings.maximum;
  if (residuals.size() >= 2 && previous > 0.0) {
    const double before = residuals[residuals.size() - 2];
    // Eq. 4.12: eta_k = gamma (r_k / r_{k-1})^alpha, and not much below the last one while that
    // was loose (the safeguard against a lucky residual drop, eq. 4.13).
    eta = before > 0.0 ? settings.gamma * std::pow(r / before, settings.alpha) : 0.0;
    const double safeguard = settings.gamma * std::pow(previous, settings.alpha);
    if (safeguard > 0.1) eta = std::max(eta, safeguard);
  }
  if (residuals.size() >= 2) eta = std::min(eta, settings.maximum);
  // Eq. 4.14: no tighter than the solve that takes the residual to half the Newton tolerance.
  if (r > 0.0) eta = std::max(eta, 0.5 * residual_tolerance / r);
  return std::clamp(eta, settings.floor, std::max(settings.maximum, settings.first));
}

}  // namespace geompm
