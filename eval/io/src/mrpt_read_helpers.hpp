#pragma once
// Internal to the io layer, shared by the rawlog readers (landmarks: rawlog.cpp, point clouds:
// point_cloud_rawlog.cpp): MRPT poses as Rigid3 and the sanity check every pose read goes through.
// MRPT's exception text cut to its message is public: mrpt_exception_message.hpp.

#include "relslam/core/rigid.hpp"

#include <mrpt/io/CFileGZInputStream.h>
#include <mrpt/poses/CPose3D.h>

#include <cstddef>
#include <filesystem>

#include <string>

namespace relslam::eval {

Rigid3 rigid_of(const mrpt::poses::CPose3D& pose);

// A pose from the file must be finite, each coordinate within +-max_offset, and its rotation a
// rotation: MRPT stores the matrix itself, so a flipped bit gives a shear that would bend every
// point silently.
void require_sane(const Rigid3& pose, double max_offset, const std::string& file, int record,
                  const std::string& field);

// Opens a rawlog (plain or gzip) into `in` and returns its size on disk (0 when unknown), what
// rawlog_decoded_budget() takes. Throws InputError for a missing file, a directory, a file that
// cannot be opened.
std::uintmax_t open_rawlog(const std::filesystem::path& path, mrpt::io::CFileGZInputStream& in);

}  // namespace relslam::eval
