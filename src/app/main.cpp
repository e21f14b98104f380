// vofdem: mpiexec -n N vofdem -options_file_yaml scene.yaml [-option value ...]
#include "vofdem/core/Runtime.hpp"
#include "vofdem/core/Simulation.hpp"

static const char help[] = "vofdem: particle-laden flows with free surfaces, heat transfer and melting.\n"
                           "Usage: mpiexec -n N vofdem -options_file_yaml scene.yaml [-option value ...]\n\n";

static PetscErrorCode Run() {
  vofdem::Simulation sim;
  PetscBool          help = PETSC_FALSE;

  PetscFunctionBeginUser;
  PetscCall(PetscOptionsHasHelp(nullptr, &help));
  PetscCall(sim.Create(PETSC_COMM_WORLD));
  PetscCall(sim.SetFromOptions());
  if (!help) {
    PetscCall(sim.SetUp());
    PetscCall(sim.View(PETSC_VIEWER_STDOUT_WORLD));
    PetscCall(sim.Run());
  }
  PetscCall(sim.Destroy());
  PetscFunctionReturn(0);
}

int main(int argc, char **argv) {
  if (int code = vofdem::Initialize(&argc, &argv, help)) return code;
  return vofdem::Finalize(Run());
}
