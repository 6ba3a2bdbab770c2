#pragma once
// Our own check of a PLY or PCD point file's header before Open3D 0.16 reads it. Internal to
// eval/sources (cloud_planes.cpp).
//
// Open3D trusts the header: it sizes the cloud to the point count the header states before it
// reads a point, so a PCD header stating 10^8 points over one data line took 5 GB and 108 s and
// gave 10^8 points at the origin, and a PLY header stating 2·10^9 vertices threw bad_alloc. It
// leaves a coordinate the file lacks uninitialised (PLY) and reads coordinate types it does not
// know as 0 (PCD). So the header must state 1 to kMaxCloudPoints points with x, y and z each of
// a type Open3D reads, and a PCD file must hold the data its header states.

#include <filesystem>

namespace relslam::eval {

// Throws InputError (file:line: field: problem) for a header that breaks the rules above;
// files that pass may still be refused by Open3D (a PLY shorter than its header says).
void check_ply_header(const std::filesystem::path& path);
void check_pcd_header(const std::filesystem::path& path);

}  // namespace relslam::eval
