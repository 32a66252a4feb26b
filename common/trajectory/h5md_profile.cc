#include "common/trajectory/h5md_profile.h"

#include "common/trajectory/run_parameters.h"

// The tables name only the fields a row needs; the others keep their member
// defaults on purpose. GCC 12 warns about that even for designated initializers.
#pragma GCC diagnostic ignored "-Wmissing-field-initializers"

namespace coolgas::schema {
namespace {

using enum DataType;
using enum RowCount;
using enum ValueRule;
using namespace layout;

// Version 2 adds the effects (viscoelastic restitution, ballistic
// aggregation): the viscoelastic model's constant (a /parameters row of
// run_parameters.cc), and for the aggregation layout per-particle id (fill
// value -1 marks an absent aggregate), mass and diameter, and the aggregate
// observables. Version 3 writes the model-specific /parameters only for the
// models that use them; the rows stay, as kPerModel.
void append_aggregation_layout(Profile& p) {
  p.version = 3;
  const auto aggregation = [](ElementSpec e) {
    e.presence = Presence::kPerModel;
    e.since = 2;
    e.only_in = layout::Layout::kAggregation;
    return e;
  };
  p.elements.push_back(aggregation({.path = kId, .type = kInt32, .row = {kParticles},
                                    .meaning = "aggregate id, -1 if absent", .fill = layout::kAbsentId}));
  p.elements.push_back(aggregation({.path = kMass, .row = {kParticles}, .rule = kFinite,
                                    .meaning = "aggregate mass"}));
  p.elements.push_back(aggregation({.path = kDiameter, .row = {kParticles}, .rule = kFinite,
                                    .meaning = "aggregate diameter"}));
  p.elements.push_back(aggregation({.path = kAggregates, .type = kInt64, .rows = kObservableRows,
                                    .meaning = "number of aggregates"}));
  p.elements.push_back(aggregation({.path = kMeanMass, .rows = kObservableRows, .rule = kFinite,
                                    .meaning = "mean aggregate mass"}));
  p.elements.push_back(aggregation({.path = kLargestMass, .rows = kObservableRows, .rule = kFinite,
                                    .meaning = "largest aggregate mass"}));
}

// Version 5 adds rough particles (collision.beta > -1): their spins in the
// dumps, as 3-vectors whatever the dimension (disks spin about z, their x
// and y components 0), and their rotational energy among the observables;
// the attributes beta and inertia are rows of the parameter table.
void append_rough_particles(Profile& p) {
  p.elements.push_back({.path = kAngularVelocity, .row = {kParticles, Extent{.size = 3}}, .rule = kFinite,
                        .meaning = "angular velocities (2D: about z)", .presence = Presence::kOptional,
                        .since = int(kRoughSchemaVersion), .rough_only = true});
  p.elements.push_back({.path = kRotationalEnergy, .rows = kObservableRows, .rule = kFinite,
                        .meaning = "rotational energy per particle", .presence = Presence::kOptional,
                        .since = int(kRoughSchemaVersion), .rough_only = true});
}

// Version 6 adds mixtures ([[species]]): each particle's species in the
// dumps (an index into the species table: int32, written with every dump, so
// each dump reads alone) and each species' kinetic energy per particle of
// that species among the observables; the species table is three
// /parameters arrays of the parameter table.
void append_mixtures(Profile& p) {
  p.elements.push_back({.path = kSpecies, .type = kInt32, .row = {kParticles}, .rule = kSpeciesIndex,
                        .meaning = "species of each particle (mixtures)", .presence = Presence::kOptional,
                        .since = int(kMixtureSchemaVersion), .mixture_only = true});
  p.elements.push_back({.path = kSpeciesKineticEnergy, .row = {kSpeciesExtent}, .rows = kObservableRows,
                        .rule = kFinite, .meaning = "kinetic energy per particle of each species (mixtures)",
                        .presence = Presence::kOptional, .since = int(kMixtureSchemaVersion),
                        .mixture_only = true});
}

DataType type_of(const ParameterField::Member& m) {
  if (std::holds_alternative<std::int64_t RunParameters::*>(m)) return kInt64;
  if (std::holds_alternative<std::string RunParameters::*>(m)) return kVlenString;
  return kFloat64;
}

// The /parameters attributes: one row per field of the run-parameter table.
void append_parameters(Profile& p) {
  for (const ParameterField& f : run_parameter_fields())
    p.attributes.push_back({.group = kParameters,
                            .name = f.name,
                            .type = type_of(f.member),
                            .at_least = f.at_least,
                            .above = f.above,
                            .per_species = std::holds_alternative<std::vector<double> RunParameters::*>(f.member),
                            .meaning = f.meaning,
                            .presence = is_optional(f)         ? Presence::kOptional
                                        : is_model_specific(f) ? Presence::kPerModel
                                                               : Presence::kRequired,
                            .since = f.since});
}

// Version 1, row for row as in data-schema/h5md-profile.md. Later versions append.
Profile make_profile() {
  Profile p;
  p.version = 1;
  p.groups = {
      {.path = kH5md, .meaning = "H5MD metadata"},
      {.path = kAuthor, .meaning = "who ran the simulation"},
      {.path = kCreator, .meaning = "the program that wrote the file"},
      {.path = kBox, .meaning = "the periodic cubic box"},
      {.path = kParameters, .meaning = "the run's inputs, as attributes"},
      {.path = kRestart, .meaning = "per-dump counters needed to resume"},
  };
  p.attributes = {
      {.group = kH5md, .name = "version", .type = kInt32, .length = 2, .equals = "[1, 1]", .meaning = "H5MD version"},
      {.group = kAuthor, .name = "name", .type = kVlenString, .meaning = "user running the simulation"},
      {.group = kCreator, .name = "name", .type = kVlenString, .meaning = "creating program"},
      {.group = kCreator, .name = "version", .type = kVlenString, .meaning = "its version"},
      // The page says int32; coolgas 0.1 writes int64 and MDAnalysis reads either.
      // d = 3 for spheres, 2 for disks (system.dimension); it sets the d extents below.
      {.group = kBox, .name = "dimension", .type = kInteger, .at_least = 1, .at_most = 3, .meaning = "dimension d"},
      {.group = kBox,
       .name = "boundary",
       .type = kVlenString,
       .equals = "periodic",
       .per_dimension = true,
       .meaning = "boundary conditions"},
  };
  p.elements = {
      {.path = kBoxEdges, .row = {kDimension, kDimension}, .rule = kBoxMatrix, .meaning = "diag(L, L, L)"},
      {.path = kPosition, .row = {kParticles, kDimension}, .rule = kInsideBox, .meaning = "centres"},
      {.path = kImage, .type = kInt32, .row = {kParticles, kDimension}, .meaning = "image counts"},
      {.path = kVelocity, .row = {kParticles, kDimension}, .rule = kFinite, .meaning = "velocities"},
      {.path = kKineticEnergy, .rows = kObservableRows, .rule = kFinite, .meaning = "E per particle"},
      {.path = kCollisions, .type = kInt64, .rows = kObservableRows, .meaning = "collisions so far"},
      {.path = kCollisionsPerParticle,
       .rows = kObservableRows,
       .rule = kFinite,
       .meaning = "2 x collisions / N"},
      {.path = kCollisionsBelowDelta,
       .type = kInt64,
       .rows = kObservableRows,
       .meaning = "collisions below delta so far"},
      {.path = kTotalMomentum,
       .row = {kDimension},
       .rows = kObservableRows,
       .rule = kFinite,
       .meaning = "total momentum"},
  };
  p.datasets = {
      {.path = kRestartTime, .type = kFloat64, .same_as = kPositionTime, .meaning = "dump time"},
      {.path = kRestartCollisions, .meaning = "collisions at the dump"},
      {.path = kRestartBelowDelta, .meaning = "collisions below delta at the dump"},
  };
  append_parameters(p);
  append_aggregation_layout(p);
  append_rough_particles(p);
  append_mixtures(p);
  // Version 4 added the driven gas's optional /parameters (above), 5 rough
  // particles, 6 mixtures.
  p.version = int(kMixtureSchemaVersion);
  p.schema_version = {kParameters, "schema_version"};
  p.particle_count = {kParameters, "N"};
  p.box_side = {kParameters, "L"};
  p.frames_from = kPosition;
  p.observable_rows_from = kKineticEnergy;
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

std::string shape_rule(RowCount rows, const std::vector<Extent>& row, std::optional<int> d) {
  std::string s = "(";
  s.append(row_count_symbol(rows));
  for (const Extent& e : row) {
    s.append(", ");
    s.append(e.particles  ? "N"
             : e.species  ? "S"
             : !e.dimension ? std::to_string(e.size)
             : d          ? std::to_string(*d)
                          : "d");
  }
  s.append(row.empty() ? ",)" : ")");
  return s;
}

}  // namespace coolgas::schema
