#include "rawlog_record_stream.hpp"

#include <mrpt/io/CFileGZOutputStream.h>
#include <mrpt/io/CFileOutputStream.h>
#include <mrpt/serialization/CArchive.h>

#include <stdexcept>

namespace relslam::eval {

RawlogRecordStream::RawlogRecordStream(const std::filesystem::path& path, bool gzip) : name_(path.string()) {
  if (gzip) {
    auto s = std::make_unique<mrpt::io::CFileGZOutputStream>();
    if (!s->open(name_, 1)) throw std::runtime_error(name_ + ": cannot create file");
    stream_ = std::move(s);
  } else {
    auto s = std::make_unique<mrpt::io::CFileOutputStream>();
    if (!s->open(name_, mrpt::io::OpenMode::TRUNCATE)) throw std::runtime_error(name_ + ": cannot create file");
    stream_ = std::move(s);
  }
}

void RawlogRecordStream::write(const mrpt::obs::CActionCollection& actions, const mrpt::obs::CSensoryFrame& frame) {
  if (!stream_) throw std::logic_error(name_ + ": write after close");
  record_.clear();
  auto archive = mrpt::serialization::archiveFrom(record_);
  archive << actions << frame;
  const auto bytes = static_cast<std::size_t>(record_.getPosition());  // bytes written since clear()
  if (stream_->Write(record_.getRawBufferData(), bytes) != bytes)
    throw std::runtime_error(name_ + ": write failed (disk full?)");
}

}  // namespace relslam::eval
