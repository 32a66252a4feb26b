// One dump's row of the coolgas-displacement table (data-schema/tsv-tables.md,
// "coolgas-displacement"), from its arrays and the reference dump's. The
// tool writes it; the Python module (analyze/python/) returns it.
#pragma once
#include <cstdint>
#include <span>
#include <string>
#include <vector>

#include "analyze/displacement/displacement.h"
#include "common/tsv.h"

namespace coolgas {

const std::vector<std::string>& displacement_columns();

// The row of the dump at time t (box side L; positions, images and
// velocities as DisplacementOrigin takes them) measured from `origin`, the
// dump at t_ref: t dt msd msd_err vacf vacf_norm T D_apparent. InputError if
// the particle count or the box side differs from the origin's.
TableBlock displacement_row(const DisplacementOrigin& origin, double t_ref, double L_ref, double t, double L,
                            std::span<const double> positions, std::span<const std::int32_t> images,
                            std::span<const double> velocities);

}  // namespace coolgas
