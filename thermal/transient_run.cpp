#include "transient_run.hpp"

#include <algorithm>
#include <stdexcept>

namespace centrec::thermal {

namespace {
TransientSample sample(FilmOperator& op, double t, const std::vector<double>& y) {
  TransientSample s;
  s.t = t;
  s.balance = op.balance(t, y.data());
  const ThermalFields f = op.fields(t, y.data());
  s.T_surface_max = *std::max_element(f.T_surface.begin(), f.T_surface.end());
  return s;
}
}  // namespace

TransientResult run_transient(FilmOperator& op, const std::vector<double>& y0, const TransientSettings& s) {
  if (!(s.t_end > 0.0)) throw std::invalid_argument("transient: t_end must be > 0");
  if (s.n_outputs < 2) throw std::invalid_argument("transient: n_outputs must be >= 2");
  op.freeze_inputs(false);
  // Kinks of the inputs inside (0, t_end): restart points.
  std::vector<double> kinks;
  for (const TimeFactor* f : {&op.model().flux_time, &op.model().flow_time})
    for (const double b : f->breakpoints())
      if (b > 0.0 && b < s.t_end) kinks.push_back(b);
  std::sort(kinks.begin(), kinks.end());
  TransientResult r;
  std::vector<double> y = y0;
  CvodeIntegrator cv(op, s.integrator, 0.0, y);
  r.samples.push_back(sample(op, 0.0, y));
  std::size_t next_kink = 0;
  for (int k = 1; k < s.n_outputs; ++k) {
    const double t_out = s.t_end * k / (s.n_outputs - 1);
    while (next_kink < kinks.size() && kinks[next_kink] <= t_out) {
      const double tk = kinks[next_kink++];
      if (tk > cv.time()) {
        cv.advance(tk, y);
        cv.reinit(tk, y);
      }
    }
    cv.advance(t_out, y);
    r.samples.push_back(sample(op, t_out, y));
  }
  r.y_end = y;
  r.stats = cv.stats();
  return r;
}

}  // namespace centrec::thermal
