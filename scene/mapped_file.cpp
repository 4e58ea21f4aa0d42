#include "scene/mapped_file.h"

#include <fcntl.h>
#include <sys/mman.h>
#include <sys/stat.h>
#include <unistd.h>

#include <cerrno>
#include <cstring>
#include <utility>

#include "scene/usda_parser.h"

namespace fluence::usd {

namespace {

// Closes a file descriptor on every way out.
struct FileDescriptor {
    int fd;
    ~FileDescriptor() {
        if (fd >= 0) ::close(fd);
    }
};

}  // namespace

SharedBytes mapFile(const std::string& path) {
    FileDescriptor file{::open(path.c_str(), O_RDONLY | O_CLOEXEC | O_NONBLOCK)};
    if (file.fd < 0) throw FileError("cannot open '" + path + "': " + std::strerror(errno));
    struct stat info {};
    if (::fstat(file.fd, &info) != 0 || !S_ISREG(info.st_mode))
        throw FileError("cannot read '" + path + "': not a regular file");
    auto size = static_cast<std::size_t>(info.st_size);
    if (size == 0) return std::make_shared<const std::string_view>();
    void* address = ::mmap(nullptr, size, PROT_READ, MAP_PRIVATE, file.fd, 0);
    if (address == MAP_FAILED) throw FileError("cannot read '" + path + "': " + std::strerror(errno));
    SharedBytes mapping(new std::string_view(static_cast<const char*>(address), size),
                        [](const std::string_view* view) {
                            ::munmap(const_cast<char*>(view->data()), view->size());
                            delete view;
                        });
    // Pages past the end of a file that shrank since fstat would fault when read: check again.
    if (::fstat(file.fd, &info) != 0 || static_cast<std::size_t>(info.st_size) < size)
        throw FileError("cannot read '" + path + "': the file shrank while it was being opened (still being written?)");
    return mapping;
}

SharedBytes holdBytes(std::vector<char> bytes) {
    auto held = std::make_shared<std::pair<std::vector<char>, std::string_view>>(std::move(bytes), std::string_view());
    held->second = std::string_view(held->first.data(), held->first.size());
    return SharedBytes(held, &held->second);
}

}  // namespace fluence::usd
