/**
 * @file    amLandmarkPoints.h
 * @brief   Named points of a landmark set (amCardiacLandmarks' output: points with the string
 *          point data "Name"), for the filters that take electrodes or a stimulus site from it.
 */
#ifndef amLandmarkPoints_h
#define amLandmarkPoints_h

#include <string>
#include <vector>

class vtkPolyData;

namespace amLandmarkPoints
{
/// The positions of the named points, in order, as x y z triples; false with why when the set has
/// no "Name" array or lacks one of the names.
bool Named(vtkPolyData* landmarks, const std::vector<std::string>& names, std::vector<double>& xyz, std::string& why);
}

#endif
