#include "data-schema/h5md_profile.h"

// The tables name only the fields a row needs; the others keep their member
// defaults on purpose. GCC 12 warns about that even for designated initializers.
#pragma GCC diagnostic ignored "-Wmissing-field-initializers"

namespace coolgas::schema {
namespace {

using enum DataType;
using enum RowCount;
using enum ValueRule;

// Version 2 adds the effects models: the viscoelastic model's constant,
// and for ballistic aggregation per-particle id (fill value -1 marks an
// absent aggregate), mass and diameter, and the aggregate observables. All
// optional: a file has them when its model uses them.
void append_version_2(Profile& p) {
  p.version = 2;
  p.attributes.push_back({.group = "/parameters",
                          .name = "viscoelastic_b",
                          .type = kFloat64,
                          .meaning = "viscoelastic material constant b",
                          .presence = Presence::kOptional,
                          .since = 2});
  const auto optional2 = [](ElementSpec e) {
    e.presence = Presence::kOptional;
    e.since = 2;
    return e;
  };
  p.elements.push_back(optional2({.path = "/particles/all/id", .type = kInt32, .row = {kParticles},
                                  .meaning = "aggregate id, -1 if absent"}));
  p.elements.push_back(optional2({.path = "/particles/all/mass", .row = {kParticles}, .rule = kFinite,
                                  .meaning = "aggregate mass"}));
  p.elements.push_back(optional2({.path = "/particles/all/diameter", .row = {kParticles}, .rule = kFinite,
                                  .meaning = "aggregate diameter"}));
  p.elements.push_back(optional2({.path = "/observables/aggregates", .type = kInt64, .rows = kObservableRows,
                                  .meaning = "number of aggregates"}));
  p.elements.push_back(optional2({.path = "/observables/mean_mass", .rows = kObservableRows, .rule = kFinite,
                                  .meaning = "mean aggregate mass"}));
  p.elements.push_back(optional2({.path = "/observables/largest_mass", .rows = kObservableRows, .rule = kFinite,
                                  .meaning = "largest aggregate mass"}));
}

// Version 1, row for row as in data-schema/h5md-profile.md. Later versions append.
Profile make_profile() {
  Profile p;
  p.version = 1;
  p.groups = {
      {.path = "/h5md", .meaning = "H5MD metadata"},
      {.path = "/h5md/author", .meaning = "who ran the simulation"},
      {.path = "/h5md/creator", .meaning = "the program that wrote the file"},
      {.path = "/particles/all/box", .meaning = "the periodic cubic box"},
      {.path = "/parameters", .meaning = "the run's inputs, as attributes"},
      {.path = "/restart", .meaning = "per-dump counters needed to resume"},
  };
  p.attributes = {
      {.group = "/h5md", .name = "version", .type = kInt32, .length = 2, .equals = "[1, 1]", .meaning = "H5MD version"},
      {.group = "/h5md/author", .name = "name", .type = kVlenString, .meaning = "user running the simulation"},
      {.group = "/h5md/creator", .name = "name", .type = kVlenString, .meaning = "creating program"},
      {.group = "/h5md/creator", .name = "version", .type = kVlenString, .meaning = "its version"},
      // The page says int32; coolgas 0.1 writes int64 and MDAnalysis reads either.
      {.group = "/particles/all/box", .name = "dimension", .type = kInteger, .equals = "3", .meaning = "dimension"},
      {.group = "/particles/all/box",
       .name = "boundary",
       .type = kVlenString,
       .length = 3,
       .equals = "[periodic, periodic, periodic]",
       .meaning = "boundary conditions"},
      {.group = "/parameters", .name = "schema_version", .type = kInt64, .at_least = 1, .meaning = "profile version"},
      {.group = "/parameters", .name = "program_version", .type = kVlenString, .meaning = "simulator version"},
      {.group = "/parameters", .name = "scene", .type = kVlenString, .meaning = "effective scene (TOML)"},
      {.group = "/parameters", .name = "seed", .type = kInt64, .meaning = "random seed"},
      {.group = "/parameters", .name = "N", .type = kInt64, .at_least = 1, .meaning = "number of particles"},
      {.group = "/parameters", .name = "L", .type = kFloat64, .meaning = "box side"},
      {.group = "/parameters", .name = "phi", .type = kFloat64, .meaning = "volume fraction"},
      {.group = "/parameters", .name = "T0", .type = kFloat64, .meaning = "initial temperature"},
      {.group = "/parameters", .name = "model", .type = kVlenString, .meaning = "collision model"},
      {.group = "/parameters", .name = "r0", .type = kFloat64, .meaning = "coefficient of restitution"},
      {.group = "/parameters", .name = "delta", .type = kFloat64, .meaning = "elastic below this normal speed"},
  };
  p.elements = {
      {.path = "/particles/all/box/edges", .row = {kThree, kThree}, .rule = kBoxMatrix, .meaning = "diag(L, L, L)"},
      {.path = "/particles/all/position", .row = {kParticles, kThree}, .rule = kInsideBox, .meaning = "centres"},
      {.path = "/particles/all/image", .type = kInt32, .row = {kParticles, kThree}, .meaning = "image counts"},
      {.path = "/particles/all/velocity", .row = {kParticles, kThree}, .rule = kFinite, .meaning = "velocities"},
      {.path = "/observables/kinetic_energy", .rows = kObservableRows, .rule = kFinite, .meaning = "E per particle"},
      {.path = "/observables/collisions", .type = kInt64, .rows = kObservableRows, .meaning = "collisions so far"},
      {.path = "/observables/collisions_per_particle",
       .rows = kObservableRows,
       .rule = kFinite,
       .meaning = "2 x collisions / N"},
      {.path = "/observables/collisions_below_delta",
       .type = kInt64,
       .rows = kObservableRows,
       .meaning = "collisions below delta so far"},
      {.path = "/observables/total_momentum",
       .row = {kThree},
       .rows = kObservableRows,
       .rule = kFinite,
       .meaning = "total momentum"},
  };
  p.datasets = {
      {.path = "/restart/time", .type = kFloat64, .same_as = "/particles/all/position/time", .meaning = "dump time"},
      {.path = "/restart/collisions", .meaning = "collisions at the dump"},
      {.path = "/restart/collisions_below_delta", .meaning = "collisions below delta at the dump"},
  };
  append_version_2(p);
  p.schema_version = {"/parameters", "schema_version"};
  p.particle_count = {"/parameters", "N"};
  p.box_side = {"/parameters", "L"};
  p.frames_from = "/particles/all/position";
  p.observable_rows_from = "/observables/kinetic_energy";
  return p;
}

}  // namespace

std::string_view type_name(DataType t) {
  switch (t) {
    case kInt32:
      return "int32";
    case kInt64:
      return "int64";
    case kFloat64:
      return "float64";
    case kVlenString:
      return "vlen str";
    case kInteger:
      return "integer";
  }
  return "?";
}

std::string_view row_count_symbol(RowCount r) { return r == kFrames ? "F" : "K"; }

const Profile& h5md_profile() {
  static const Profile profile = make_profile();
  return profile;
}

std::string shape_rule(RowCount rows, const std::vector<Extent>& row) {
  std::string s = "(";
  s.append(row_count_symbol(rows));
  for (const Extent& e : row) {
    s.append(", ");
    s.append(e.particles ? "N" : std::to_string(e.size));
  }
  s.append(row.empty() ? ",)" : ")");
  return s;
}

}  // namespace coolgas::schema
