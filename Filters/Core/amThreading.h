/**
 * @class   amThreading
 * @brief   Selects a multi-threaded vtkSMPTools backend once per process.
 *
 * ParaView 5.11's VTK defaults to the Sequential SMP backend, which leaves the second core idle.
 * Filters call amThreading::Initialize() in their constructor: unless the user chose a backend
 * through VTK_SMP_BACKEND_IN_USE, it switches to STDThread. Results never depend on the thread
 * count (every parallel loop in Anatomesh writes disjoint outputs or reduces deterministically).
 */
#ifndef amThreading_h
#define amThreading_h

#include "AnatomeshFiltersCoreModule.h" // export macro

class ANATOMESHFILTERSCORE_EXPORT amThreading
{
public:
  static void Initialize();
};

#endif
