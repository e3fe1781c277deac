#pragma once
// A run's claim on its output folder (docs/outputs.md "Run folders"): one run writes into a
// folder at a time, and a folder never holds the files of two runs. A new run is refused in a
// folder that holds another run's results (naming them) or an interrupted run's checkpoint
// (saying how to resume it), unless the user asks to overwrite, which removes the earlier
// run's files first; a folder another live process is writing into is refused even then.
// The claim is DIR/.centrec-run.lock (the process id and the command), removed when the
// claim ends; a lock whose process is gone (killed) is taken over.
#include <string>
#include <vector>

namespace centrec::io {

enum class FolderUse {
  new_run,    // refuse a folder holding another run's files
  overwrite,  // remove them first
  resume,     // continue the interrupted run in it (its checkpoint is needed)
};

// The files of a run that a folder holds (summary.json, dem.h5, checkpoint.h5, ...).
std::vector<std::string> run_files_in(const std::string& dir);

class RunFolderClaim {
 public:
  // Throws std::invalid_argument naming the folder, what it holds and what to do.
  RunFolderClaim(const std::string& dir, const std::string& command, FolderUse use);
  ~RunFolderClaim();
  RunFolderClaim(const RunFolderClaim&) = delete;
  RunFolderClaim& operator=(const RunFolderClaim&) = delete;

 private:
  std::string lock_;
};

}  // namespace centrec::io
