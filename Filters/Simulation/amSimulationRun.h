/**
 * @file    amSimulationRun.h
 * @brief   Which run of a heart solver made a heart output: field data "SimulationRun", one id per
 *          run across every solver of the process, so the torso and ECG filters know when their
 *          cached results still hold.
 */
#ifndef amSimulationRun_h
#define amSimulationRun_h

class vtkDataObject;

namespace amSimulationRun
{
/// A new id, unique in the process.
long long Next();
/// Records the id on a solver's output.
void Stamp(vtkDataObject* output, long long id);
/// The id a heart carries; for a heart no solver made, its modification time shifted out of the
/// solvers' range.
long long Of(vtkDataObject* heart);
}

#endif
