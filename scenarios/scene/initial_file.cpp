#include "scenarios/scene/initial_file.hpp"
#include "scenarios/scene/input_file.hpp"

#include <algorithm>
#include <filesystem>
#include <numeric>
#include <stdexcept>

#include "core/hdf5.hpp"
#include "scenarios/run/run_output.hpp"

namespace carom {

namespace {

/// A particle as stored in the file, species by the file's own index.
struct StoredParticles {
  std::vector<std::string> species_names;  ///< The file's species, by its index.
  std::vector<std::int32_t> species;
  std::vector<Vec3> position, velocity, spin;
  std::vector<double> radius;
  std::string what;                        ///< "snapshot 000004 (t = 0.1 s)", "checkpoint (t = ...)".
};

std::vector<Vec3> rows3(const std::vector<double>& flat) {
  std::vector<Vec3> out(flat.size() / 3);
  for (std::size_t i = 0; i < out.size(); ++i) out[i] = Vec3(flat[3 * i], flat[3 * i + 1], flat[3 * i + 2]);
  return out;
}

StoredParticles read_run_file(const h5::File& file, const InitialFile& from, const std::string& context) {
  StoredParticles s;
  const h5::Group species = file.open_group("species");
  s.species_names = species.read_strings("name");
  const h5::Group snapshots = file.open_group("snapshots");
  const std::vector<std::string> names = snapshots.children();
  const auto count = static_cast<std::int64_t>(names.size());
  const std::int64_t index = from.snapshot < 0 ? count + from.snapshot : from.snapshot;
  if (index < 0 || index >= count)
    throw SceneError(context + ": snapshot = " + std::to_string(from.snapshot) + " is out of range: the file holds " +
                     std::to_string(count) + " snapshots (0 ... " + std::to_string(count - 1) +
                     ", or -1 for the last, -2 for the one before ...)");
  const h5::Group snapshot = snapshots.open_group(names[static_cast<std::size_t>(index)]);
  const hsize_t n = snapshot.open_dataset("radius").size();
  s.position = rows3(snapshot.read<double>("position", {n, 3}));
  s.velocity = rows3(snapshot.read<double>("velocity", {n, 3}));
  s.spin = rows3(snapshot.read<double>("spin", {n, 3}));
  s.radius = snapshot.read<double>("radius", {n});
  s.species = snapshot.read<std::int32_t>("species", {n});
  s.what = "snapshot " + names[static_cast<std::size_t>(index)] + " (t = " +
           format_number(snapshot.attribute<double>("time")) + " s)";
  return s;
}

StoredParticles read_checkpoint_file(const InitialFile& from, const std::string& context) {
  if (from.snapshot_given)
    throw SceneError(context + ": is a checkpoint, which holds one state and no snapshots; remove "
                     "initial.from_file.snapshot");
  const Checkpoint checkpoint = read_checkpoint(from.path);
  // The stored scene gives the species' names, and the method restored from it each particle's
  // state at the checkpoint's time.
  const Scene stored = parse_scene(checkpoint.info.scene_text, from.path + " (stored scene)");
  StoredParticles s;
  for (const Species& species : stored.system.species) s.species_names.push_back(species.name);
  const std::unique_ptr<CollisionMethod> method =
      restore_method(stored.system, stored.method, checkpoint.method_state());
  const ParticleStore& p = method->system().particles;
  std::vector<std::size_t> order(p.size());
  std::iota(order.begin(), order.end(), std::size_t{0});
  std::sort(order.begin(), order.end(), [&](auto a, auto b) { return p.id[a] < p.id[b]; });
  const double time = method->time();
  for (std::size_t i : order) {
    s.position.push_back(method->position(i));
    s.velocity.push_back(method->velocity(i));
    s.spin.push_back(method->spin(i));
    s.radius.push_back(p.radius[i]);
    s.species.push_back(static_cast<std::int32_t>(p.species[i]));
  }
  s.what = "checkpoint (t = " + format_number(time) + " s)";
  return s;
}

std::string quoted_list(const std::vector<std::string>& names) {
  std::string out;
  for (const std::string& name : names) out += (out.empty() ? "\"" : ", \"") + name + "\"";
  return out;
}

}  // namespace

std::vector<FileParticle> read_initial_file(const Scene& scene) {
  const InitialFile& from = *scene.from_file;
  const std::string context = from.where + ": initial.from_file.path = \"" + from.written + "\"" +
                              (from.written != from.path ? " (" + from.path + ")" : std::string());
  std::error_code missing;
  if (!std::filesystem::exists(from.path, missing))
    throw SceneError(context + ": no such file (a relative path is relative to the scene file's folder)");
  require_regular_file(from.path, context);  // a directory, a device or a FIFO: refused before reading
  StoredParticles stored;
  try {
    std::string kind;
    {
      const h5::File file = h5::File::open(from.path, false);
      if (file.has_attribute("kind")) kind = file.attribute<std::string>("kind");
      if (kind == "carom run") stored = read_run_file(file, from, context);
    }
    if (kind == "carom checkpoint") {
      stored = read_checkpoint_file(from, context);
    } else if (kind != "carom run") {
      throw SceneError(context + ": is not a carom run file (run.h5) or checkpoint (checkpoint.h5): its root "
                       "attribute 'kind' is \"" + kind + "\"");
    }
  } catch (const SceneError&) {
    throw;
  } catch (const std::exception& e) {
    throw SceneError(context + ": cannot be read: " + e.what());
  }

  // Species by name; every particle's radius must be its scene species' diameter / 2.
  const std::vector<Species>& species = scene.system.species;
  std::vector<std::string> scene_names;
  for (const Species& s : species) scene_names.push_back(s.name);
  std::vector<std::int64_t> to_scene(stored.species_names.size(), -1);
  for (std::size_t f = 0; f < stored.species_names.size(); ++f) {
    const auto it = std::find(scene_names.begin(), scene_names.end(), stored.species_names[f]);
    if (it != scene_names.end()) to_scene[f] = it - scene_names.begin();
  }
  std::vector<FileParticle> particles(stored.radius.size());
  for (std::size_t k = 0; k < particles.size(); ++k) {
    const std::int32_t f = stored.species[k];
    if (f < 0 || static_cast<std::size_t>(f) >= stored.species_names.size())
      throw SceneError(context + ": " + stored.what + ", row " + std::to_string(k) + ": species index " +
                       std::to_string(f) + " is not one of the file's " +
                       std::to_string(stored.species_names.size()) + " species (a damaged file?)");
    const std::string& name = stored.species_names[static_cast<std::size_t>(f)];
    if (to_scene[static_cast<std::size_t>(f)] < 0)
      throw SceneError(context + ": " + stored.what + " holds particles of species \"" + name +
                       "\", which this scene does not define (scene species: " + quoted_list(scene_names) +
                       "; file species: " + quoted_list(stored.species_names) +
                       "); species are matched by name");
    const auto s = static_cast<std::uint32_t>(to_scene[static_cast<std::size_t>(f)]);
    if (stored.radius[k] != species[s].radius())
      throw SceneError(context + ": " + stored.what + ", row " + std::to_string(k) + ": a particle of species \"" +
                       name + "\" has radius " + format_number(stored.radius[k]) +
                       " m, but the scene's species \"" + name + "\" has diameter " +
                       format_number(species[s].diameter) + " m (radius " + format_number(species[s].radius()) +
                       " m); the radius must equal the scene's diameter / 2 (set species." + name +
                       ".diameter = " + format_number(2.0 * stored.radius[k]) + ")");
    particles[k] = FileParticle{s, stored.position[k], stored.velocity[k], stored.spin[k]};
  }
  return particles;
}

}  // namespace carom
