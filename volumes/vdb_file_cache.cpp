#include "volumes/vdb_file_cache.h"

#include <algorithm>
#include <atomic>
#include <filesystem>
#include <map>
#include <memory>
#include <mutex>
#include <stdexcept>
#include <utility>

namespace fluence::volumes {

namespace {

std::string describe(const std::string& path, const std::string& name, int index) {
    std::string grid = "grid '" + name + "'";
    if (index > 0) grid += " (index " + std::to_string(index) + ")";
    return "OpenVDB file '" + path + "', " + grid;
}

// One open file and the grids read from it so far, by the name OpenVDB gives them ("NAME" for the
// first of a name, "NAME[k]" for the others).
class OpenFile {
public:
    explicit OpenFile(const std::string& path) : file_(path) {
        file_.open(/*delayLoad=*/false);  // grids are read whole, never mapped
    }

    openvdb::GridBase::ConstPtr grid(const std::string& path, const std::string& name, int index) {
        std::lock_guard lock(mutex_);
        std::string uniqueName = index == 0 ? name : name + "[" + std::to_string(index) + "]";
        if (openvdb::GridBase::ConstPtr grid = grids_[uniqueName].lock()) return grid;
        openvdb::GridBase::ConstPtr grid;
        try {
            grid = file_.readGrid(uniqueName);
        } catch (const openvdb::KeyError&) {
            throw std::runtime_error(describe(path, name, index) + ": no such grid" + listing());
        }
        grids_[uniqueName] = grid;
        return grid;
    }

private:
    std::string listing() {
        std::string names;
        for (auto it = file_.beginName(); it != file_.endName(); ++it)
            names += (names.empty() ? "" : ", ") + it.gridName();
        return names.empty() ? " (the file has no grids)" : " (the file has " + names + ")";
    }

    std::mutex mutex_;
    openvdb::io::File file_;
    std::map<std::string, std::weak_ptr<const openvdb::GridBase>> grids_;
};

class FileTable {
public:
    FileTable() { openvdb::initialize(); }

    std::shared_ptr<OpenFile> open(const std::string& path, const std::string& name, int index) {
        std::string key = std::filesystem::absolute(path).lexically_normal().string();
        std::lock_guard lock(mutex_);
        if (auto it = files_.find(key); it != files_.end()) return it->second;
        if (!std::filesystem::is_regular_file(key))
            throw std::runtime_error(describe(path, name, index) + ": no such file");
        std::shared_ptr<OpenFile> file;
        try {
            file = std::make_shared<OpenFile>(key);
        } catch (const openvdb::Exception& e) {
            throw std::runtime_error(describe(path, name, index) + ": not a readable OpenVDB file (" + e.what() + ")");
        }
        ++opened_;
        return files_.emplace(key, std::move(file)).first->second;
    }

    std::size_t opened() const { return opened_; }

private:
    std::mutex mutex_;
    std::map<std::string, std::shared_ptr<OpenFile>> files_;
    std::atomic<std::size_t> opened_ = 0;
};

FileTable& fileTable() {
    static FileTable table;
    return table;
}

}  // namespace

openvdb::GridBase::ConstPtr readVdbGrid(const std::string& path, const std::string& name, int index) {
    index = std::max(index, 0);
    std::shared_ptr<OpenFile> file = fileTable().open(path, name, index);
    try {
        return file->grid(path, name, index);
    } catch (const openvdb::Exception& e) {
        throw std::runtime_error(describe(path, name, index) + ": cannot be read (" + e.what() + ")");
    }
}

std::size_t vdbFilesOpened() { return fileTable().opened(); }

}  // namespace fluence::volumes
