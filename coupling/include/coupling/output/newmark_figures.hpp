#pragma once
// The figures of Newmark's displacement (analyses.lem.critical_seismic_coefficient.acceleration_record):
// figures/newmark_record.svg, the record times its scale (g) against time with k_c, where the mass starts to slide
// downslope (and -k_c, where the reversed record makes it slide); figures/newmark_displacement.svg, the
// displacement (m) at each sample, the record as given and reversed. Long records are thinned for drawing (the
// largest and least acceleration of each of about 1 500 stretches kept).
#include <string>

#include "coupling/analyses/run_results.hpp"
#include "coupling/scene/scene.hpp"

namespace coupling {

std::string newmark_record_svg(const AccelerationRecordInput& record, double yield_coefficient,
                               const std::string& title);
std::string newmark_displacement_svg(const AccelerationRecordInput& record, const NewmarkOutcome& newmark,
                                     const std::string& title);

}  // namespace coupling
