#pragma once
// Internal to the io layer: an MRPT rawlog file open for writing, one action-first record
// (CActionCollection, then CSensoryFrame) at a time: what every rawlog writer of the harness
// shares (rawlog.cpp's landmark observations, scan_rawlog.cpp's laser scans and depth images).

#include <mrpt/io/CMemoryStream.h>
#include <mrpt/io/CStream.h>
#include <mrpt/obs/CActionCollection.h>
#include <mrpt/obs/CSensoryFrame.h>

#include <filesystem>
#include <memory>
#include <string>

namespace relslam::eval {

class RawlogRecordStream {
 public:
  // Creates (truncates) the file, gzip-compressed when asked; std::runtime_error if it cannot.
  RawlogRecordStream(const std::filesystem::path& path, bool gzip);
  // One record; std::runtime_error after close() or when the disk refuses it.
  void write(const mrpt::obs::CActionCollection& actions, const mrpt::obs::CSensoryFrame& frame);
  void close() { stream_.reset(); }
  const std::string& name() const { return name_; }

 private:
  std::unique_ptr<mrpt::io::CStream> stream_;
  // Each record is serialised into memory first and written with one call: MRPT's archive
  // issues one stream write per field, which is several times slower on a file stream.
  mrpt::io::CMemoryStream record_;
  std::string name_;
};

}  // namespace relslam::eval
