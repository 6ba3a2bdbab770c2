#pragma once
// Indices the Relative Plane classes use to refer to each other (thesis 4.4.3.1: RltXPointsS
// keeps master vectors of RltPlanes and RltXPoints; everything else holds indices into them).

namespace relslam::plane {

using PlaneId = int;   // index of an RltPlane in RltXPointsS::planes(); also its creation order
using XPointId = int;  // index of an RltXPoint in RltXPointsS::xpoints(); printed X0, X1, …
inline constexpr int kNone = -1;

}  // namespace relslam::plane
