#include "apps/render_checkpoint.h"

#include <algorithm>
#include <cstring>
#include <fstream>

#include "core/binary_stream.h"
#include "core/film_state.h"
#include "output/atomic_file.h"

namespace fluence::app {

namespace {

constexpr char kMagic[] = "FLUENCE CHECKPOINT\n";
constexpr std::uint32_t kMaxEntries = 1024, kMaxEntryLength = 1u << 20;

// "seed: 1 in the checkpoint, 2 now; frame: ..." for every entry that differs ("" if none).
std::string differences(const CheckpointFingerprint& saved, const CheckpointFingerprint& now) {
    std::string text;
    auto add = [&](const std::string& line) { text += (text.empty() ? "" : "; ") + line; };
    for (const auto& [name, value] : now) {
        auto it = std::find_if(saved.begin(), saved.end(), [&](const auto& e) { return e.first == name; });
        if (it == saved.end())
            add(name + ": not in the checkpoint");
        else if (it->second != value)
            add(name + ": " + it->second + " in the checkpoint, " + value + " now");
    }
    for (const auto& [name, value] : saved)
        if (std::none_of(now.begin(), now.end(), [&](const auto& e) { return e.first == name; }))
            add(name + ": " + value + " in the checkpoint, not set now");
    return text;
}

}  // namespace

std::string checkpointPath(const std::string& outputPath) { return outputPath + ".checkpoint"; }

void writeCheckpoint(const std::string& path, const CheckpointFingerprint& fingerprint, int samplesDone,
                     const Film& film, const CryptomatteFilm* cryptomatte) {
    output::writeAtomically(path, [&](const std::string& tempPath) {
        std::ofstream out(tempPath, std::ios::binary);
        if (!out) throw output::outputError(path, "cannot create " + tempPath);
        out.write(kMagic, sizeof kMagic - 1);
        writeBinary(out, kCheckpointVersion);
        writeBinary(out, kByteOrderMark);
        writeBinary(out, static_cast<std::uint32_t>(fingerprint.size()));
        for (const auto& [name, value] : fingerprint) {
            writeBinaryString(out, name);
            writeBinaryString(out, value);
        }
        writeBinary(out, static_cast<std::uint32_t>(samplesDone));
        writeFilmState(film, out);
        writeBinary(out, static_cast<std::uint8_t>(cryptomatte != nullptr));
        if (cryptomatte) cryptomatte->writeState(out);
        out.close();
        if (!out) throw output::outputError(path, "write failed (disk full?)");
    });
}

int readCheckpoint(const std::string& path, const CheckpointFingerprint& fingerprint, Film& film,
                   CryptomatteFilm* cryptomatte) {
    std::ifstream in(path, std::ios::binary);
    if (!in) throw CheckpointError("cannot open the checkpoint " + path);
    try {
        char magic[sizeof kMagic - 1];
        readBinary(in, magic, sizeof magic);
        if (std::memcmp(magic, kMagic, sizeof magic) != 0) throw CheckpointError(path + " is not a Fluence checkpoint");
        if (const auto version = readBinary<std::uint32_t>(in); version != kCheckpointVersion)
            throw CheckpointError("the checkpoint " + path + " is of version " + std::to_string(version) +
                                  " (this build reads version " + std::to_string(kCheckpointVersion) + ")");
        if (readBinary<std::uint32_t>(in) != kByteOrderMark)
            throw CheckpointError("the checkpoint " + path + " was written on a machine of another byte order");
        const auto entries = readBinary<std::uint32_t>(in);
        if (entries > kMaxEntries) throw BinaryReadError(std::to_string(entries) + " fingerprint entries");
        CheckpointFingerprint saved;
        for (std::uint32_t i = 0; i < entries; ++i) {
            std::string name = readBinaryString(in, kMaxEntryLength);
            saved.emplace_back(std::move(name), readBinaryString(in, kMaxEntryLength));
        }
        if (const std::string diff = differences(saved, fingerprint); !diff.empty())
            throw CheckpointMismatch("the checkpoint " + path + " is of another render (" + diff + ")");
        const auto samplesDone = readBinary<std::uint32_t>(in);
        readFilmState(in, film);
        if (const bool saved = readBinary<std::uint8_t>(in) != 0; saved != (cryptomatte != nullptr))
            throw FilmStateError(saved ? "it holds Cryptomatte layers, and this render has none"
                                       : "it holds no Cryptomatte layers");
        if (cryptomatte) cryptomatte->readState(in);
        if (in.peek() != std::char_traits<char>::eof()) throw BinaryReadError("data after the film state");
        return static_cast<int>(samplesDone);
    } catch (const BinaryReadError& e) {
        throw CheckpointError("the checkpoint " + path + " is damaged: " + e.what());
    } catch (const FilmStateError& e) {
        throw CheckpointError("the checkpoint " + path + " does not fit this render: " + e.what());
    }
}

}  // namespace fluence::app
