#include "analyze/clusters/cluster_definition.h"

#include <algorithm>
#include <cmath>

#include "common/error.h"
#include "common/tsv.h"

namespace coolgas {

namespace {

[[noreturn]] void refuse(const std::string& text, const std::string& why) {
  throw InputError("--definition " + shown(text) + ": " + why +
                   " (allowed: cells, contact, or contact:CUTOFF with CUTOFF >= 1 in sigma)");
}

}  // namespace

ClusterDefinition parse_cluster_definition(const std::string& text) {
  ClusterDefinition d;
  if (text == "cells") return d;
  d.kind = ClusterDefinition::Kind::kContact;
  if (text == "contact") return d;
  if (text.rfind("contact:", 0) != 0) refuse(text, "not a cluster definition");
  const std::string value = text.substr(8);
  std::size_t used = 0;
  try {
    d.cutoff = std::stod(value, &used);
  } catch (const std::exception&) {
    refuse(text, "the cutoff is not a number");
  }
  if (used != value.size()) refuse(text, "the cutoff is not a number");
  if (!(d.cutoff >= 1) || !std::isfinite(d.cutoff))
    refuse(text, "spheres never come closer than sigma, so a cutoff below 1 bonds none");
  return d;
}

std::string definition_name(const ClusterDefinition& d) {
  return d.contact() ? "contact:" + format_number(d.cutoff) : "cells";
}

std::string contact_text(const ClusterDefinition& d, bool mixture) {
  if (mixture)
    return "particles closer than " + format_number(d.cutoff) +
           " sigma_ij (sigma_ij = (sigma_i + sigma_j)/2, the pair's contact distance from its species' diameters; "
           "centre distance, periodic minimum image) are bonded; bonded particles form a cluster";
  return "particles closer than " + format_number(d.cutoff) +
         " sigma (centre distance, periodic minimum image) are bonded; bonded particles form a cluster";
}

void check_cutoff(const ClusterDefinition& d, double L, const std::string& where, std::span<const double> diameter) {
  const double widest = diameter.empty() ? 1.0 : *std::max_element(diameter.begin(), diameter.end());
  if (!d.contact() || d.cutoff * widest <= L / 2) return;
  const std::string bond = widest == 1 ? "the cutoff"
                                       : "the longest bond, the cutoff times the largest diameter " +
                                             format_number(widest) + " = " + format_number(d.cutoff * widest) + ",";
  throw InputError(where + ": --definition " + definition_name(d) + ": " + bond +
                   " exceeds half the box side, L/2 = " + format_number(L / 2) + " (distances are minimum images)");
}

}  // namespace coolgas
