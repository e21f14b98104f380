// Open MPI start-up settings for runs that stay on one machine, chosen before MPI_Init.
//
// Debian's Open MPI 4.1 spends ~0.3 s of every start on things a one-node run never uses: a
// singleton (a program started without mpiexec) forks an `orted` daemon and waits for it, and every
// process opens the network transports of the `cm` layer, whose Omni-Path library (libpsm2) sleeps in
// its constructor, before falling back to shared memory (`ob1`). Measured on the 2-core machine:
// ex30 at a/h 4 starts and finishes in 0.42 s as a singleton and 0.09 s with these settings;
// `mpiexec -n 2` 0.43 s and 0.19 s. A vofdem run pays it once; a test suite of 400 short runs pays
// it 400 times.
//
// Nothing the user chose is overridden: a variable already in the environment (OMPI_MCA_pml or
// OMPI_MCA_mtl, from the shell or from mpiexec --mca) is left alone, and VOFDEM_MPI_DEFAULTS=0 turns
// all of this off. Jobs that span machines (mpiexec reports fewer local ranks than ranks) are left to
// Open MPI's own choice, since there the network layers matter.
#pragma once

namespace vofdem {

// Sets OMPI_MCA_* environment variables for the cases above (a no-op under other MPI libraries,
// which ignore them). Call before MPI_Init.
void ApplyMpiStartupDefaults();

}  // namespace vofdem
