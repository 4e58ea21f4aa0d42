// The OpenVDB files the volumes read, each opened once per process and shared.
//
// INTERNAL to volumes/ (and its tests): this header includes OpenVDB, which is heavy, so only .cpp
// files include it; the rest of Fluence sees volumes/vdb_grid.h.
//
// A file is keyed by its absolute, lexically normalised path, so several fields (density,
// temperature) and several prims reading one file open it once. An opened file stays open (reading
// header and grid descriptors only); a grid is read whole on first request and shared while anyone
// holds it (the cache keeps a weak reference, so a grid nobody uses is freed and, if asked for again,
// read again from the open file). Thread-safe: one lock for the table of files, one per file for
// reading from it.
//
// UsdVol's fieldIndex picks among grids of one name: index 0 (or a negative index: fieldIndex not
// authored) is the first in file order, index k the (k+1)-th, which OpenVDB names "NAME[k]" when
// it writes duplicates.
//
// ERRORS are std::runtime_error naming the file and the grid: no such file, not an OpenVDB file, no
// grid of that name (the message lists the grids the file has), index out of range.
#pragma once

#include <openvdb/openvdb.h>

#include <cstddef>
#include <string>

namespace fluence::volumes {

// Grid `name` (the index-th of that name) of the OpenVDB file at `path`, read whole.
openvdb::GridBase::ConstPtr readVdbGrid(const std::string& path, const std::string& name, int index = 0);

// How many times any OpenVDB file has been opened by this process (each file once).
std::size_t vdbFilesOpened();

}  // namespace fluence::volumes
