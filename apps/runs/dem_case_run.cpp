// The DEM run of a case: the engine's run, then the shared outputs.
#include "runs/dem_case_run.hpp"

#include "io/atomic_write.hpp"
#include "runs/dem_run.hpp"
#include "runs/dem_run_report.hpp"
#include "runs/interrupt.hpp"

namespace centrec::runs {

DemEngine native_engine(const std::optional<io::RunCheckpoint>& ck) {
  return [ck](const config::CaseFile& cf, const config::DemCase& dc, const std::string& out_dir) {
    return DemRun(cf, dc, out_dir, ck).run();
  };
}

io::DemRunResult run_dem_case(const config::CaseFile& cf, const config::DemCase& dc, const std::string& out_dir,
                              const DemEngine& engine) {
  io::ensure_directory(out_dir);
  io::DemRunResult r = engine(cf, dc, out_dir);
  // A Ctrl-C while the outputs are written waits for them (seconds) instead of losing the
  // finished run, then stops the caller.
  {
    const InterruptGuard writing;
    write_dem_run_report(out_dir, cf, dc, r);
  }
  if (const int signal = InterruptGuard::received()) throw OutputsInterrupted(signal, out_dir);
  return r;
}

}  // namespace centrec::runs
