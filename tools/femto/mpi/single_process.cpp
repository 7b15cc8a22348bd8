// RenderProcesses when femto is built without MPI: always one process.
#include "render_processes.h"

#include <cstdlib>
#include <iostream>

namespace femto::cli {

RenderProcesses::RenderProcesses() {}
RenderProcesses::~RenderProcesses() = default;
void RenderProcesses::shareTiles(bool share) { sharing_ = share; }

void RenderProcesses::abortJob(const std::string& message) const {
  std::cerr << "error: " << message << '\n';
  std::exit(1);
}

}  // namespace femto::cli
