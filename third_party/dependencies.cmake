# External packages, all from Debian 12 (scripts/setup.sh installs them).
# Only CMake glue lives in third_party/: no outside code is vendored.
#
#   Eigen3 3.4        libeigen3-dev       linear algebra (every layer)
#   MRPT 2.5          libmrpt-dev         EKF baseline, rawlog I/O (eval only)
#   OpenCV 4.6        libopencv-dev       map rendering (eval only)
#   nlohmann_json 3.11 nlohmann-json3-dev scenarios, manifests (eval only)
#   CLI11 2.1         libcli11-dev        command line (eval only)
#   nanoflann 1.4     libnanoflann-dev    k-d tree for scoring (eval only)
#   GTest 1.12        libgtest-dev        tests
#   benchmark 1.7     libbenchmark-dev    benchmarks
#   Open3D 0.16       libopen3d-dev       the RANSAC plane baseline (eval/sources only; optional)

find_package(Eigen3 3.4 REQUIRED NO_MODULE)
find_package(nlohmann_json 3.11 REQUIRED)
find_package(CLI11 2.1 REQUIRED)
find_package(nanoflann 1.4 REQUIRED)
find_package(Ceres 2.1 REQUIRED)  # relslam_relax and the harness's batch optimum
find_package(OpenCV 4 REQUIRED COMPONENTS core imgproc imgcodecs videoio)
foreach(module IN ITEMS mrpt-slam mrpt-obs mrpt-io mrpt-serialization mrpt-poses)
  find_package(${module} REQUIRED)
endforeach()

# Optional: without it relative_plane.extractor ransac_open3d says it is not built.
# -DRELSLAM_WITH_OPEN3D=OFF leaves it out even when installed.
option(RELSLAM_WITH_OPEN3D "Build the Open3D RANSAC plane baseline when Open3D is found" ON)
set(RELSLAM_OPEN3D OFF)
if(RELSLAM_WITH_OPEN3D)
  find_package(Open3D QUIET)  # its version file accepts only an exact version
  if(Open3D_FOUND)
    set(RELSLAM_OPEN3D ON)
  endif()
endif()
message(STATUS "relslam: Open3D RANSAC baseline ${RELSLAM_OPEN3D}")

add_library(relslam_mrpt INTERFACE)
target_link_libraries(relslam_mrpt INTERFACE mrpt::slam mrpt::obs mrpt::io mrpt::serialization mrpt::poses)
add_library(relslam_opencv INTERFACE)
target_include_directories(relslam_opencv SYSTEM INTERFACE ${OpenCV_INCLUDE_DIRS})
target_link_libraries(relslam_opencv INTERFACE ${OpenCV_LIBS})

if(RELSLAM_BUILD_TESTS)
  find_package(GTest 1.12 REQUIRED)
endif()
if(RELSLAM_BUILD_BENCHMARKS)
  find_package(benchmark 1.7 REQUIRED)
endif()
