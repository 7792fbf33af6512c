#include "amHeartSolver.h"

amHeartSolver::amHeartSolver()
  : HeartRegions{ 5 }
  , RegionArrayName(nullptr)
  , FiberArrayName(nullptr)
  , StimulusCenter{ 0, 0, 0 }
  , StimulusRadius(10.0)
  , EndocardialConductionVelocity(0.0)
  , TimeStep(0.1)
  , EndTime(500.0)
  , OutputInterval(1.0)
  , NumberOfHeartNodes(0)
  , WallSeconds(0)
{
  this->SetRegionArrayName("Region");
  this->SetFiberArrayName("Fibers");
}

amHeartSolver::~amHeartSolver()
{
  this->SetRegionArrayName(nullptr);
  this->SetFiberArrayName(nullptr);
}

void amHeartSolver::AddHeartRegion(int label)
{
  this->HeartRegions.push_back(label);
  this->Modified();
}

void amHeartSolver::RemoveAllHeartRegions()
{
  if (!this->HeartRegions.empty())
  {
    this->HeartRegions.clear();
    this->Modified();
  }
}

void amHeartSolver::PrintSelf(ostream& os, vtkIndent indent)
{
  this->Superclass::PrintSelf(os, indent);
  os << indent << "HeartRegions:";
  for (int r : this->HeartRegions)
    os << " " << r;
  os << "\n";
  os << indent << "RegionArrayName: " << (this->RegionArrayName ? this->RegionArrayName : "(none)")
     << " FiberArrayName: " << (this->FiberArrayName ? this->FiberArrayName : "(none)") << "\n";
  os << indent << "StimulusCenter: " << this->StimulusCenter[0] << " " << this->StimulusCenter[1] << " "
     << this->StimulusCenter[2] << " StimulusRadius: " << this->StimulusRadius << "\n";
  os << indent << "EndocardialConductionVelocity: " << this->EndocardialConductionVelocity << "\n";
  os << indent << "TimeStep: " << this->TimeStep << " EndTime: " << this->EndTime
     << " OutputInterval: " << this->OutputInterval << "\n";
}
