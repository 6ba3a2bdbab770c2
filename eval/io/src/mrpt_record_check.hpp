#pragma once
// Our own bounds on MRPT's serialisation framing, applied before MRPT's deserialiser sees a byte.
// Internal to eval/io (rawlog.cpp, point_cloud_rawlog.cpp).
//
// MRPT 2.5's deserialiser trusts the file: element counts go straight to resize() (a 684-byte
// file asked for 12.7 GB), a bool byte of 2 is undefined behaviour, and a mutated odometry
// action segfaults. An MRPT object is `0x80 | name length`, the class name, a version byte,
// the class's fields, then the end flag 0x88; there is no payload length. So we walk the
// fields ourselves for the classes a landmark SLAM rawlog and a point-cloud rawlog need, in the
// versions MRPT 2.5 reads, checking every count against a sane maximum while copying the bytes into one record
// buffer; only a record that walked cleanly is handed to MRPT, which then reads exactly those
// bytes. Any other class is refused by name: without its layout its extent is unknown.

#include <cstddef>
#include <functional>
#include <stdexcept>
#include <span>
#include <string>
#include <vector>

namespace relslam::eval {

// What is wrong with a record and where inside it ("CSensoryFrame.observations[2].
// CObservationBearingRange.sensedData"); the caller adds the file and record number.
class RecordProblem : public std::runtime_error {
 public:
  RecordProblem(std::string field, const std::string& problem, bool truncated = false)
      : std::runtime_error(problem), field_(std::move(field)), truncated_(truncated) {}
  const std::string& field() const { return field_; }
  bool truncated() const { return truncated_; }  // the input ended inside the record

 private:
  std::string field_;
  bool truncated_;
};

// The most bytes one record (a sensory frame, an action collection, an observation) may hold:
// a million bearing-range measurements, far above any landmark sensor's frame. MRPT keeps each
// 16-byte measurement in 88 bytes (with its covariance matrix), so one record's decoding stays
// near 100 MB; at 64 MiB a 124 KB gzip file of one record took 742 MB.
inline constexpr std::size_t kMaxRecordBytes = std::size_t{16} << 20;

// The most pixels either way of an image or range layer the cloud walk lets MRPT size: the
// cloud reader's own bound, kMaxImageSide of point_cloud_rawlog.hpp (which checks they agree).
inline constexpr int kMaxWalkedImageSide = 8192;

// Reads up to n bytes into the buffer; fewer only at the end of the input.
using ByteReader = std::function<std::size_t(void* buffer, std::size_t n)>;

// The classes accepted at the top level of a rawlog, for messages and the README.
const std::vector<std::string>& accepted_record_classes();

// Copies the next top-level object of `read` into `record` (cleared first), checking it as the
// header comment says. Returns false when the input ends before the object's first byte.
// Throws RecordProblem otherwise.
bool read_checked_record(const ByteReader& read, std::vector<unsigned char>& record);

// The same walk for the point-cloud reader (point_cloud_rawlog.hpp), records of at most
// `max_bytes`: CObservation3DRangeScan (v9-10; its images, CImage v6-9, are walked and cut from
// the record, since the reader does not use them and MRPT would decode a JPEG of any size its
// header claims; cameras TCamera v4-6; pixel labels are refused), CObservationVelodyneScan
// (v0-2), CObservationPointCloud (v0, holding CSimplePointsMap v9-10, CColouredPointsMap v9 or
// CPointsMapXYZI v0), at the top level or in a CSensoryFrame (with the observations above), and
// CActionCollection. Every count is checked against what the record may still hold before MRPT
// would size anything by it; an image or range layer is at most 8192 pixels either way.
bool read_checked_cloud_record(const ByteReader& read, std::vector<unsigned char>& record, std::size_t max_bytes);

// The class of the MRPT object whose header starts `bytes`, without its namespace, after the
// same header checks as the walk above (an MRPT header, an identifier); `path` names the place
// in messages. The point-cloud reader (point_cloud_rawlog.hpp) checks each record's class so
// before MRPT decodes it. Throws RecordProblem.
std::string record_class_name(std::span<const unsigned char> bytes, const std::string& path);

}  // namespace relslam::eval
