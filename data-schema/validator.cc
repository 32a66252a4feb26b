#include "data-schema/validator.h"

#include <algorithm>
#include <cmath>
#include <map>
#include <optional>
#include <set>

#include "common/hdf5_file.h"
#include "common/interrupt.h"
#include "common/trajectory/collision_models.h"
#include "common/trajectory/frame_reader.h"
#include "common/trajectory/layout.h"
#include "common/trajectory/run_parameters.h"
#include "common/tsv.h"
#include "data-schema/hdf5_inspect.h"
#include "data-schema/value_checks.h"

namespace coolgas::schema {
namespace {

std::string path_of(std::string_view base, std::string_view name) {
  return std::string(base) + "/" + std::string(name);
}

std::string attr_text(const AttributeRef& a) { return path_of(a.group, a.name); }

constexpr const char* kDamagedText = "cannot be read: its object header is damaged";

// "x, x" (n times x), as an array attribute is shown.
std::string repeated(const std::string& x, int n) {
  std::string s;
  for (int i = 0; i < n; ++i) s.append(i ? ", " : "").append(x);
  return s;
}

// An element whose step, time and value were found right and agree in rows.
struct GoodElement {
  std::string path;
  RowCount kind;
  hsize_t rows;
};

// One validation run over one open file. Structure checks come first; value
// scans run only on datasets whose type and shape were found right.
class Checker {
 public:
  Checker(hid_t file, const std::string& path, const Profile& profile, const ValidateOptions& options)
      : file_(file), path_(path), profile_(profile), options_(options) {}

  Report run() {
    read_schema_version();
    read_model();
    read_completion();
    for (const GroupSpec& g : profile_.groups) check_group(g);
    try {
      d_ = layout::dimension_of(file_);
    } catch (const InputError&) {
      d_ = 3;  // the attribute check reports any other value
    }
    read_species();
    for (const AttributeSpec& a : profile_.attributes) check_attribute(a);
    check_driving();
    check_rough();
    check_mixture();
    read_box_parameters();
    for (const ElementSpec& e : profile_.elements) guarded(e.path, [&] { check_element(e); });
    check_shared_rows(RowCount::kFrames, profile_.frames_from);
    check_shared_rows(RowCount::kObservableRows, profile_.observable_rows_from);
    for (const DatasetSpec& d : profile_.datasets) guarded(d.path, [&] { check_dataset(d); });
    guarded(layout::kPosition, [&] { check_overlaps(); });
    report_.summary = {N_.value_or(0), rows_of(profile_.frames_from), rows_of(profile_.observable_rows_from),
                       file_version_, interrupted_};
    return std::move(report_);
  }

 private:
  void problem(std::string_view path, std::string what) {
    report_.problems.push_back({std::string(path), std::move(what)});
  }

  // A read failure inside one object (corrupt chunk, ...) is that object's
  // problem, not the end of the run; a signal is the end of it.
  template <class F>
  void guarded(std::string_view path, F&& body) {
    try {
      body();
    } catch (const Interrupted&) {
      throw;
    } catch (const std::exception& e) {
      problem(path, std::string("cannot read: ") + e.what());
    }
  }

  // Rows added in a later schema version are optional in files of earlier
  // versions; a per-model row is required when the file's model has it.
  bool required(Presence presence, int since, bool model_has_it = false) const {
    if (presence == Presence::kPerModel) return model_has_it;
    return presence == Presence::kRequired && since <= file_version_;
  }

  bool model_has(const AttributeSpec& a) const { return model_ && model_uses(*model_, a.name); }
  bool model_has(const ElementSpec& e) const {
    const CollisionModelSpec* m = model_ ? find_collision_model(*model_) : nullptr;
    return m && (!e.only_in || *e.only_in == m->layout);
  }

  // The driven gas's attributes (common/trajectory/run_parameters.h): a
  // driven run writes both, and says the schema version that added them.
  void check_driving() {
    const std::string group(layout::kParameters);
    AttributeFound found;
    const bool power = read_attribute(file_, group, "driving_power", found);
    const bool period = read_attribute(file_, group, "driving_period", found);
    if (power != period)
      problem(group, std::string("attribute '") + (power ? "driving_power" : "driving_period") + "' without '" +
                         (power ? "driving_period" : "driving_power") + "': a driven run writes both");
    if ((power || period) && file_version_ < kDrivingSchemaVersion)
      problem(group, "the driven gas's attributes in a file of schema version " + std::to_string(file_version_) +
                         "; they came with version " + std::to_string(kDrivingSchemaVersion));
  }

  // Rough particles (collision_models.h, beta): a rough run writes beta
  // (in (-1, 1]) with its inertia (in (0, 1]), for a model that has beta,
  // in a file of the version that added them, and its spins and rotational
  // energy (check_element); a smooth run none of these.
  void check_rough() {
    const std::string group(layout::kParameters);
    AttributeFound beta, inertia;
    rough_ = read_attribute(file_, group, "beta", beta);
    const bool has_inertia = read_attribute(file_, group, "inertia", inertia);
    if (rough_ != has_inertia)
      problem(group, std::string("attribute '") + (rough_ ? "beta" : "inertia") + "' without '" +
                         (rough_ ? "inertia" : "beta") + "': a run of rough particles writes both");
    if (!rough_) return;
    if (file_version_ < kRoughSchemaVersion)
      problem(group, "rough particles' attributes in a file of schema version " + std::to_string(file_version_) +
                         "; they came with version " + std::to_string(kRoughSchemaVersion));
    if (model_ && !model_uses(*model_, "beta"))
      problem(group, "attribute 'beta' in a file of model " + *model_ + ", which has no rough particles");
    if (!(beta.first_number > -1 && beta.first_number <= 1))
      problem(group, "attribute 'beta' is " + beta.text + "; rough particles have beta in (-1, 1]");
    if (has_inertia && !(inertia.first_number > 0 && inertia.first_number <= 1))
      problem(group, "attribute 'inertia' is " + inertia.text + "; a moment of inertia per m a^2 is in (0, 1]");
  }

  // A mixture's species table (run_parameters.h): S, the length of
  // species_fraction, read before the attribute rows of that length are
  // checked (0: no table, or one unreadable, which check_mixture reports).
  void read_species() {
    species_ = species_array("species_fraction").size();
  }
  // Whether the particles carry their species (has_particle_species).
  bool particle_species() const { return species_ > 0 && model_ && model_keeps_species(*model_); }
  std::vector<double> species_array(const std::string& name) {
    const std::string group(layout::kParameters);
    if (kind_of(file_, group) != ObjectKind::kGroup) return {};
    try {
      h5::Handle g = h5::open_group(file_, group);
      if (!h5::has_attr(g.id(), name)) return {};
      return h5::read_attr_doubles(g.id(), name, kMaxFileSpecies);
    } catch (const std::exception&) {
      return {};
    }
  }

  // A mixture writes its three species arrays together, of one length, in a
  // file of the version that added them: fractions in (0, 1] adding up to 1,
  // diameters and masses finite and above 0; and each particle's species
  // and each species' energy (check_element). Equal particles none of these.
  void check_mixture() {
    const std::string group(layout::kParameters);
    const char* const names[] = {"species_fraction", "species_diameter", "species_mass"};
    std::vector<double> table[3];
    int present = 0;
    for (int k = 0; k < 3; ++k) present += !(table[k] = species_array(names[k])).empty();
    if (present == 0) return;
    if (present < 3 || table[1].size() != species_ || table[2].size() != species_) {
      problem(group, "a mixture's species_fraction, species_diameter and species_mass are written together, one "
                     "value per species each");
      return;
    }
    if (file_version_ < kMixtureSchemaVersion)
      problem(group, "a mixture's attributes in a file of schema version " + std::to_string(file_version_) +
                         "; they came with version " + std::to_string(kMixtureSchemaVersion));
    double sum = 0;
    for (std::size_t k = 0; k < species_; ++k) {
      sum += table[0][k];
      if (!(table[0][k] > 0 && table[0][k] <= 1 && table[1][k] > 0 && std::isfinite(table[1][k]) &&
            table[2][k] > 0 && std::isfinite(table[2][k])))
        problem(group, "species " + std::to_string(k) + " has fraction " + number_text(table[0][k]) + ", diameter " +
                           number_text(table[1][k]) + ", mass " + number_text(table[2][k]) +
                           "; a fraction is in (0, 1], a diameter and a mass finite and above 0");
    }
    if (!(std::fabs(sum - 1.0) <= 1e-9))
      problem(group, "the species fractions add up to " + number_text(sum) + ", not 1");
  }

  // The model decides which per-model rows are required; an unknown one is a problem of its own.
  void read_model() {
    AttributeFound m;
    if (!read_attribute(file_, layout::kParameters, "model", m) || m.type != type_name(DataType::kVlenString)) return;
    model_ = m.text;
    if (!find_collision_model(*model_))
      problem(layout::kParameters, "attribute 'model' is " + m.text + ", not one of " + collision_model_names());
  }

  // The /restart/time rows mark the complete dumps (layout.h); rows of a
  // later, interrupted burst are not checked. Without a usable marker every
  // row counts.
  void read_completion() {
    const std::string rt(layout::kRestartTime);
    if (kind_of(file_, rt) != ObjectKind::kDataset) return;
    h5::Handle t = h5::open_dataset(file_, rt);
    if (h5::shape(t.id()).size() != 1) return;
    const std::vector<double> times = h5::read_all<double>(t.id());
    if (times.empty()) return;
    complete_[RowCount::kFrames] = times.size();
    last_dump_ = times.back();
    const std::string ot = path_of(profile_.observable_rows_from, "time");
    if (kind_of(file_, ot) != ObjectKind::kDataset) return;
    h5::Handle o = h5::open_dataset(file_, ot);
    if (h5::shape(o.id()).size() != 1) return;
    const std::vector<double> obs = h5::read_all<double>(o.id());
    complete_[RowCount::kObservableRows] =
        hsize_t(std::upper_bound(obs.begin(), obs.end(), times.back()) - obs.begin());
  }

  // The rows of a time series up to the last complete dump (its times do not
  // decrease, or that is reported).
  hsize_t rows_until(hid_t time) const {
    const std::vector<double> t = h5::read_all<double>(time);
    return hsize_t(std::upper_bound(t.begin(), t.end(), *last_dump_) - t.begin());
  }

  std::optional<hsize_t> complete(RowCount kind) const {
    const auto it = complete_.find(kind);
    if (it == complete_.end()) return std::nullopt;
    return it->second;
  }

  Scan scan(RowCount kind) const {
    return {.block_values = options_.block_values, .rows = complete(kind).value_or(Scan{}.rows)};
  }

  // A missing or nonsensical version (reported by the attribute check) holds
  // the file to everything this profile knows.
  void read_schema_version() {
    AttributeFound v;
    const AttributeRef& ref = profile_.schema_version;
    const bool usable = read_attribute(file_, ref.group, ref.name, v) && v.type.starts_with("int") && v.dims.empty() &&
                        v.first_integer >= 1;
    file_version_ = usable ? static_cast<int>(v.first_integer) : profile_.version;
  }

  void check_group(const GroupSpec& g) {
    const ObjectKind kind = kind_of(file_, g.path);
    if (kind == ObjectKind::kMissing && required(g.presence, g.since))
      problem(g.path, "missing group (" + std::string(g.meaning) + ")");
    else if (kind == ObjectKind::kDamaged)
      problem(g.path, kDamagedText);
    else if (kind != ObjectKind::kMissing && kind != ObjectKind::kGroup)
      problem(g.path, "is not a group");
  }

  void check_attribute(const AttributeSpec& a) {
    const ObjectKind group = kind_of(file_, a.group);
    if (group == ObjectKind::kMissing || group == ObjectKind::kDamaged) return;  // reported with the group
    const std::string name = "attribute '" + std::string(a.name) + "'";
    AttributeFound found;
    if (!read_attribute(file_, a.group, a.name, found)) {
      if (required(a.presence, a.since, model_has(a)))
        problem(a.group,
                "missing " + name + " (" + std::string(type_name(a.type)) + ", " + std::string(a.meaning) + ")");
      return;
    }
    const std::vector<hsize_t> want_dims = a.per_dimension ? std::vector<hsize_t>{hsize_t(d_)}
                                           : a.per_species ? std::vector<hsize_t>{hsize_t(species_)}
                                           : a.length      ? std::vector<hsize_t>{*a.length}
                                                           : std::vector<hsize_t>{};
    std::string equals(a.equals);
    if (a.per_dimension) equals = "[" + repeated(equals, d_) + "]";
    if (found.type != type_name(a.type) && !(a.type == DataType::kInteger && found.type.starts_with("int")))
      problem(a.group,
              name + " has type " + found.type + " but the profile requires " + std::string(type_name(a.type)));
    else if (found.dims != want_dims)
      problem(a.group,
              name + " has shape " + shape_text(found.dims) + " but the profile requires " + shape_text(want_dims));
    else if (!equals.empty() && found.text != equals)
      problem(a.group, name + " is " + found.text + " but the profile requires " + equals);
    else if (a.at_least && found.first_integer < *a.at_least)
      problem(a.group, name + " is " + found.text + " but must be at least " + std::to_string(*a.at_least));
    else if (a.at_most && found.first_integer > *a.at_most)
      problem(a.group, name + " is " + found.text + " but must be at most " + std::to_string(*a.at_most));
    else if (a.above && !(std::isfinite(found.first_number) && found.first_number > *a.above))
      problem(a.group, name + " is " + found.text + " but must be a finite number above " + format_number(*a.above));
    else
      good_attributes_.insert(path_of(a.group, a.name));
  }

  // N and L are needed by shape and value rules; a bad one was reported already.
  void read_box_parameters() {
    AttributeFound n, L;
    const AttributeRef& nr = profile_.particle_count;
    const AttributeRef& lr = profile_.box_side;
    if (good_attributes_.count(attr_text(nr)) && read_attribute(file_, nr.group, nr.name, n)) N_ = n.first_integer;
    if (good_attributes_.count(attr_text(lr)) && read_attribute(file_, lr.group, lr.name, L)) L_ = L.first_number;
  }

  // Checks existence, type and shape of a series of `rows` rows shaped (R, row...).
  // Returns its open handle and row count when all are right.
  std::optional<std::pair<h5::Handle, hsize_t>> check_series(const std::string& path, DataType type, RowCount rows,
                                                             const std::vector<Extent>& row) {
    const ObjectKind kind = kind_of(file_, path);
    if (kind != ObjectKind::kDataset) {
      problem(path, kind == ObjectKind::kMissing   ? "missing dataset"
                    : kind == ObjectKind::kDamaged ? kDamagedText
                                                   : "is not a dataset");
      return std::nullopt;
    }
    h5::Handle ds = h5::open_dataset(file_, path);
    h5::Handle t(H5Dget_type(ds.id()));
    if (!type_matches(type, t.id())) {
      problem(path, "type " + describe_type(t.id()) + " but the profile requires " + std::string(type_name(type)));
      return std::nullopt;
    }
    const std::vector<hsize_t> dims = h5::shape(ds.id());
    // A resume resizes and appends to every series: one of fixed size (an
    // other program's rewrite) would fail half-way, after changing the file.
    if (!dims.empty()) {
      h5::Handle space(H5Dget_space(ds.id()));
      std::vector<hsize_t> now(dims.size()), most(dims.size());
      if (space.valid() && H5Sget_simple_extent_dims(space.id(), now.data(), most.data()) >= 0 &&
          most[0] != H5S_UNLIMITED) {
        problem(path, "has a fixed size of " + std::to_string(most[0]) +
                          " rows; a series must be chunked with unlimited rows (coolgas appends to it)");
        return std::nullopt;
      }
    }
    if (!shape_fits(dims, row)) {
      std::string what = "shape " + shape_text(dims) + " but the profile requires " + shape_rule(rows, row, d_);
      if (d_ != 3 && std::any_of(row.begin(), row.end(), [](const Extent& e) { return e.dimension; }))
        what += " (d = " + std::to_string(d_) + " from " + std::string(layout::kBox) + "/dimension)";
      if (N_ && std::any_of(row.begin(), row.end(), [](const Extent& e) { return e.particles; }))
        what += " with N = " + std::to_string(*N_) + " from " + attr_text(profile_.particle_count);
      problem(path, what);
      return std::nullopt;
    }
    return std::make_pair(std::move(ds), dims[0]);
  }

  // Rank and every fixed extent must match; N only when /parameters/N was readable.
  bool shape_fits(const std::vector<hsize_t>& dims, const std::vector<Extent>& row) const {
    if (dims.size() != row.size() + 1) return false;
    for (std::size_t k = 0; k < row.size(); ++k) {
      const Extent& e = row[k];
      const hsize_t want = e.dimension ? hsize_t(d_) : e.species ? hsize_t(species_) : e.size;
      if (e.particles ? (N_ && dims[k + 1] != static_cast<hsize_t>(*N_)) : dims[k + 1] != want) return false;
    }
    return true;
  }

  void check_element(const ElementSpec& e) {
    const ObjectKind kind = kind_of(file_, e.path);
    if (kind == ObjectKind::kMissing) {
      if (required(e.presence, e.since, model_has(e)) || (e.rough_only && rough_) ||
          (e.mixture_only && particle_species()))
        problem(e.path, "missing element (" + std::string(e.meaning) + ")");
      return;
    }
    if (e.rough_only && !rough_) return problem(e.path, "in a file of smooth particles (no /parameters/beta)");
    if (e.mixture_only && species_ == 0)
      return problem(e.path, "in a file of equal particles (no /parameters/species_fraction)");
    if (e.mixture_only && !particle_species())
      return problem(e.path, "in a file of model " + model_.value_or("?") + ", whose particles keep no species");
    if (kind == ObjectKind::kDamaged) return problem(e.path, kDamagedText);
    if (kind != ObjectKind::kGroup) return problem(e.path, "is not a group (an H5MD element holds step, time, value)");
    auto step = check_series(path_of(e.path, "step"), DataType::kInt64, e.rows, {});
    auto time = check_series(path_of(e.path, "time"), DataType::kFloat64, e.rows, {});
    auto value = check_series(path_of(e.path, "value"), e.type, e.rows, e.row);
    if (time) check_found(path_of(e.path, "time"), check_nondecreasing(time->first.id(), scan(e.rows)));
    if (value) check_values(e, value->first.id());
    if (!step || !time || !value) return;
    const hsize_t least = std::min({step->second, time->second, value->second});
    const hsize_t most = std::max({step->second, time->second, value->second});
    // An observable's complete rows are its own rows up to the last complete
    // dump: every observable must hold the same number (check_shared_rows),
    // as a resume appends to all of them from there.
    const auto done = e.rows == RowCount::kObservableRows && last_dump_ ? std::optional(rows_until(time->first.id()))
                                                                         : complete(e.rows);
    // Rows beyond the complete ones may be ragged: the burst that wrote them was cut short.
    if (done ? least < *done && least != most : least != most)
      return problem(e.path, "step, time and value have " + std::to_string(step->second) + ", " +
                                 std::to_string(time->second) + " and " + std::to_string(value->second) +
                                 " rows; they must agree");
    if (done && most > *done) interrupted_ = true;
    good_.push_back({std::string(e.path), e.rows, done ? std::min(least, *done) : least});
  }

  void check_values(const ElementSpec& e, hid_t value) {
    const std::string path = path_of(e.path, "value");
    const Scan block = scan(e.rows);
    const std::string L_from = attr_text(profile_.box_side);
    switch (e.rule) {
      case ValueRule::kAny:
        break;
      case ValueRule::kFinite:
        check_found(path, check_finite(value, block));
        break;
      case ValueRule::kInsideBox:
        if (L_) check_found(path, check_inside_box(value, *L_, L_from, block));
        break;
      case ValueRule::kBoxMatrix:
        if (L_) check_found(path, check_box_matrix(value, *L_, L_from, block));
        break;
      case ValueRule::kSpeciesIndex:
        check_found(path, check_indices_below(value, species_, "the species of /parameters/species_fraction", block));
        break;
    }
  }

  // No two spheres overlap in any complete dump (value_checks.h): read one
  // dump at a time, only when the file was found right so far (a frame
  // with NaN or a wrong shape is reported already, and not read again).
  void check_overlaps() {
    if (!report_.problems.empty() || !L_ || !good(layout::kPosition)) return;
    const Trajectory trajectory(path_, kPosition | kDiameter | kAnyDimension);
    Frame frame;
    for (std::size_t dump = 0; dump < trajectory.dump_times().size(); ++dump) {
      throw_if_interrupted(kInterruptedCheck);
      trajectory.read(dump, frame);
      const Finding f = check_no_overlaps(frame.position, frame.diameter, frame.id, frame.L, Geometry(d_));
      if (f) problem(path_of(layout::kPosition, "value"), "dump " + std::to_string(dump) + " (t = " +
                                                               number_text(frame.time) + "): " + *f);
    }
  }

  void check_found(std::string_view path, const Finding& f) {
    if (f) problem(path, *f);
  }

  const GoodElement* good(std::string_view path) const {
    for (const GoodElement& g : good_)
      if (g.path == path) return &g;
    return nullptr;
  }

  hsize_t rows_of(std::string_view element) const {
    const GoodElement* g = good(element);
    return g ? g->rows : 0;
  }

  // Every element of one kind has the rows of the reference element (or, if
  // that one is broken, of the first good one of its kind).
  void check_shared_rows(RowCount kind, std::string_view reference) {
    const GoodElement* ref = good(reference);
    for (const GoodElement& g : good_)
      if (!ref && g.kind == kind) ref = &g;
    if (!ref) return;
    reference_[kind] = *ref;
    for (const GoodElement& g : good_)
      if (g.kind == kind && g.rows != ref->rows) problem(g.path, rows_message(g.rows, *ref));
  }

  static std::string rows_message(hsize_t rows, const GoodElement& ref) {
    return std::to_string(rows) + " rows but " + std::string(row_count_symbol(ref.kind)) + " = " +
           std::to_string(ref.rows) + " from " + ref.path;
  }

  void check_dataset(const DatasetSpec& d) {
    if (kind_of(file_, d.path) == ObjectKind::kMissing && !required(d.presence, d.since)) return;
    auto ds = check_series(std::string(d.path), d.type, d.rows, {});
    if (!ds) return;
    const auto ref = reference_.find(d.rows);
    const auto done = complete(d.rows);
    const hsize_t rows = done ? std::min(ds->second, *done) : ds->second;
    if (ref != reference_.end() && rows != ref->second.rows)
      return problem(d.path, rows_message(ds->second, ref->second));
    if (done && ds->second > *done) interrupted_ = true;
    if (!d.same_as.empty() && kind_of(file_, d.same_as) == ObjectKind::kDataset) {
      h5::Handle other = h5::open_dataset(file_, std::string(d.same_as));
      if (h5::shape(other.id()).at(0) >= rows)
        check_found(d.path, check_equal(ds->first.id(), other.id(), d.same_as, scan(d.rows)));
    }
  }

  hid_t file_;
  std::string path_;
  const Profile& profile_;
  const ValidateOptions& options_;
  Report report_;
  int file_version_ = 0;
  int d_ = 3;  // box/dimension
  std::optional<double> last_dump_;  // the time of the last complete dump
  std::set<std::string> good_attributes_;
  std::optional<std::int64_t> N_;
  std::optional<double> L_;
  std::vector<GoodElement> good_;              // in table order
  std::map<RowCount, GoodElement> reference_;  // the element defining F or K
  std::optional<std::string> model_;           // /parameters/model, when readable
  bool rough_ = false;                         // /parameters/beta present: rough particles
  std::size_t species_ = 0;                    // a mixture's species (the length of /parameters/species_fraction)
  std::map<RowCount, hsize_t> complete_;       // rows of complete dumps, when /restart/time is usable
  bool interrupted_ = false;                   // rows of an interrupted burst follow them
};

}  // namespace

Report validate(const std::string& path, const Profile& profile, const ValidateOptions& options) {
  h5::Handle file = h5::open_file(path, h5::Mode::kReadOnly);
  return Checker(file.id(), path, profile, options).run();
}

std::string problem_line(const std::string& file, const Problem& p) { return file + ": " + p.path + ": " + p.what; }

std::string valid_line(const std::string& file, const Summary& s, int profile_version) {
  return file + ": valid (coolgas H5MD profile v" + std::to_string(profile_version) + ", " +
         std::to_string(s.particles) + " particles, " + std::to_string(s.frames) + " frames, " +
         std::to_string(s.observable_rows) + " observable rows" +
         (s.interrupted ? "; later rows of an interrupted or unfinished burst not checked" : "") + ")";
}

}  // namespace coolgas::schema
