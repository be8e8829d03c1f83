// walkers.Run: an evolution run under a scaffold whose children a Python
// optimiser proposes (ask/tell), writing the run folder `walkers evolve
// --learner` writes. Python drives the run's generations (EvolutionRun,
// evolve/run.h) with the external learner (evolve/external_learner.h):
// bounds() begins a generation, evaluate() evaluates its proposals with the
// GIL released, checkpoint() finishes it with the optimiser's state
// (docs/python.md).
#pragma once

#include <pybind11/pybind11.h>

namespace walkers::python {

// Adds the class Run to the module.
void BindRun(pybind11::module_& m);

}  // namespace walkers::python
