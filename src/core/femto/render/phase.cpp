#include <femto/render/phase.h>

namespace femto {

PhaseFunction::PhaseFunction(const Properties& props) : delay_(props) {}

double PhaseFunction::sampleDelay(float u) const { return delay_.sample(u); }

std::string PhaseFunction::delayString() const { return delay_.toString(); }

}  // namespace femto
