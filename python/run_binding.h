// walkers.Run: an evolution run under a scaffold whose children a Python
// optimiser proposes (ask/tell), writing the run folder `walkers evolve
// --learner` writes. The run's own loop (EvolutionRun, evolve/run.h) runs on
// a thread of its own with the external learner (evolve/external_learner.h),
// and meets Python at the learner's three questions: proposals, evaluated
// children, and the optimiser's state for the checkpoint (docs/python.md).
#pragma once

#include <pybind11/pybind11.h>

namespace walkers::python {

// Adds the class Run to the module.
void BindRun(pybind11::module_& m);

}  // namespace walkers::python
