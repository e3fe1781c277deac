#include "flux_profile.hpp"

#include <algorithm>
#include <cmath>
#include <stdexcept>

namespace centrec::thermal {

double FluxProfile::at(double z) const {
  switch (kind) {
    case Kind::uniform:
      return q;
    case Kind::gaussian: {
      const double x = (z - z_center) / sigma;
      return q_base + q * std::exp(-0.5 * x * x);
    }
    case Kind::table: {
      if (z <= table_z.front()) return table_q.front();
      if (z >= table_z.back()) return table_q.back();
      const auto it = std::upper_bound(table_z.begin(), table_z.end(), z);
      const std::size_t i = static_cast<std::size_t>(it - table_z.begin());
      const double w = (z - table_z[i - 1]) / (table_z[i] - table_z[i - 1]);
      return (1.0 - w) * table_q[i - 1] + w * table_q[i];
    }
  }
  return 0.0;
}

void FluxProfile::check() const {
  if (kind == Kind::gaussian && !(sigma > 0.0))
    throw std::invalid_argument("Gaussian flux: sigma must be > 0");
  if (aperture_mean < 0.0) throw std::invalid_argument("aperture flux must be >= 0");
  if (aperture_mean > 0.0 && kind != Kind::uniform)
    throw std::invalid_argument("a flux given at the aperture must be uniform on the film (profile uniform)");
  if (kind != Kind::table) {
    if (q < 0.0 || q_base < 0.0) throw std::invalid_argument("flux must be >= 0");
    return;
  }
  if (table_z.size() < 2 || table_z.size() != table_q.size())
    throw std::invalid_argument("flux table needs at least two (z, q) rows of equal length");
  for (std::size_t i = 0; i < table_z.size(); ++i) {
    if (i > 0 && !(table_z[i] > table_z[i - 1]))
      throw std::invalid_argument("flux table: z must increase strictly (row " + std::to_string(i + 1) + ")");
    if (!(table_q[i] >= 0.0))
      throw std::invalid_argument("flux table: q must be >= 0 (row " + std::to_string(i + 1) + ")");
  }
}

}  // namespace centrec::thermal
