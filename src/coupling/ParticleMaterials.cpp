// ParticleMaterials.hpp: the particles' thermal material per DEM type.
#include "vofdem/coupling/ParticleMaterials.hpp"

#include "vofdem/base/Options.hpp"
#include "vofdem/base/Runtime.hpp"
#include "vofdem/io/MaterialFile.hpp"

namespace vofdem {

PetscErrorCode ReadParticleTypeHeat(MPI_Comm comm, const std::vector<std::string> &typeNames, std::vector<ParticleTypeHeat> *types) {
  PetscFunctionBeginUser;
  types->assign(typeNames.size(), {});
  for (size_t t = 0; t < typeNames.size(); ++t) {
    ParticleTypeHeat &h = (*types)[t];
    h.name              = typeNames[t];
    const std::string prefix = "coupling_heat_type_" + h.name + "_";
    PetscOptionsBegin(comm, prefix.c_str(), "Particle heat of one particle type (-dem_types)", "Coupling");
    {
      OptionReader opt(PetscOptionsObject);
      PetscCall(opt.String("-material", "Material file of this type's h(T) (config/materials/NAME.yaml or a path; default: -coupling_heat_material)", &h.material));
      PetscCall(opt.Real("-specific_heat", "Specific heat of this type, constant (replaces its material's; default: the material's)", "J/(kg K)", &h.specificHeat, RealRange::Any()));
      if (h.specificHeat != -1 && !(h.specificHeat > 0)) VofdemInputError(comm, "option -%sspecific_heat: %g J/(kg K) is not positive", prefix.c_str(), (double)h.specificHeat);
      PetscCall(opt.Real("-initial_temperature", "Initial temperature of this type's particles (default: -coupling_heat_initial_temperature)", "K", &h.initialTemperature, RealRange::Any()));
      if (h.initialTemperature != -1 && !(h.initialTemperature > 0))
        VofdemInputError(comm, "option -%sinitial_temperature: %g K is not positive", prefix.c_str(), (double)h.initialTemperature);
    }
    PetscOptionsEnd();
  }
  PetscFunctionReturn(0);
}

PetscErrorCode ReadParticleMaterial(MPI_Comm comm, const std::string &option, const std::string &name, ThermalMaterial *m) {
  PetscFunctionBeginUser;
  const std::string path = FindMaterialFile(name);
  if (path.empty()) VofdemInputError(comm, "option %s: no material file '%s' (config/materials/%s.yaml or a path)", option.c_str(), name.c_str(), name.c_str());
  std::string message;
  *m      = ThermalMaterial{};
  m->name = name;
  if (!ReadThermalMaterial(path, true, m, &message)) VofdemInputError(comm, "option %s: %s", option.c_str(), message.c_str());
  PetscFunctionReturn(0);
}

PetscErrorCode BuildParticleMaterials(MPI_Comm comm, const ThermalMaterial &common, const std::vector<ParticleTypeHeat> &types, bool melting, bool conduction, PetscReal emissivity,
                                      std::vector<ThermalMaterial> *materials) {
  PetscFunctionBeginUser;
  materials->assign(std::max((size_t)1, types.size()), common);
  for (size_t t = 0; t < types.size(); ++t) {
    const ParticleTypeHeat &h = types[t];
    ThermalMaterial        &m = (*materials)[t];
    const std::string       option = "-coupling_heat_type_" + h.name + "_material";
    if (!h.material.empty()) {
      PetscCall(ReadParticleMaterial(comm, option, h.material, &m));
      m.referenceTemperature = common.referenceTemperature;  // one zero of enthalpy for the whole account
      if (emissivity >= 0) m.emissivity = emissivity;
    }
    if (h.specificHeat > 0) m.cp = PropertyTable{{}, {h.specificHeat}};
    const std::string what = types.size() > 1 || !h.material.empty() ? option : std::string("-coupling_heat_material");
    if (!m.cp.Valid() || !(m.cp.Min() > 0)) VofdemInputError(comm, "option %s: the particles of type %s have no positive specific_heat (%s)", what.c_str(), h.name.c_str(), m.path.c_str());
    if (m.latentHeat > 0 && !(m.liquidus > m.solidus && m.solidus > 0))
      VofdemInputError(comm, "option %s: the particles of type %s have latent heat but no solidus below their liquidus (%s)", what.c_str(), h.name.c_str(), m.path.c_str());
    if (conduction && (!m.k.Valid() || !(m.k.Min() > 0)))
      VofdemInputError(comm, "option %s: the particles of type %s have no positive conductivity (%s) for their contact conduction; give one or -coupling_heat_contact_conduction 0", what.c_str(), h.name.c_str(), m.path.c_str());
    if (melting && !(m.liquidus > 0))
      VofdemInputError(comm, "option -coupling_heat_melt: the particles of type %s have no liquidus to melt at (%s); give one or -coupling_heat_melt 0", h.name.c_str(), m.path.c_str());
    if (melting && m.boilingPoint > 0 && !(m.liquidus < m.boilingPoint))
      VofdemInputError(comm, "option -coupling_heat_melt: the particles of type %s would melt at their liquidus %g K, not below their boiling point %g K (%s)", h.name.c_str(), (double)m.liquidus,
                       (double)m.boilingPoint, m.path.c_str());
  }
  PetscFunctionReturn(0);
}

}  // namespace vofdem
