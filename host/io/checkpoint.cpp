#include "io/checkpoint.h"

#include <array>
#include <cstring>
#include <fstream>
#include <iterator>

#include "io/atomic_file.h"
#include "util/error.h"
#include "util/fnv.h"

namespace rad {
namespace {

constexpr char kMagic[8] = {'R', 'A', 'D', 'C', 'K', 'P', 'T', '\n'};
// 2: elements hold their own unshot power; 3: the power shot; 4: the element and patch counts
// apart (3 read a two-level solve's per-patch arrays at the element count, and refused them);
// 5: the caustic power per element (empty without mirrors or glass)
constexpr std::uint32_t kVersion = 5;

class Writer {
public:
    template <typename T>
    void put(const T& value) {
        const auto* p = reinterpret_cast<const char*>(&value);
        bytes.append(p, sizeof value);
    }
    template <typename T>
    void putArray(const std::vector<T>& values) {
        bytes.append(reinterpret_cast<const char*>(values.data()), values.size() * sizeof(T));
    }
    std::string bytes;
};

class Reader {
public:
    Reader(const std::string& bytes, const std::string& path) : bytes_(bytes), path_(path) {}
    template <typename T>
    T get() {
        T value;
        need(sizeof value);
        std::memcpy(&value, bytes_.data() + at_, sizeof value);
        at_ += sizeof value;
        return value;
    }
    template <typename T>
    void getArray(std::vector<T>& values, std::size_t count) {
        need(count * sizeof(T));
        values.resize(count);
        std::memcpy(values.data(), bytes_.data() + at_, count * sizeof(T));
        at_ += count * sizeof(T);
    }

private:
    void need(std::size_t size) {
        if (size > bytes_.size() - at_) throw FileError(path_, "the checkpoint is truncated");
    }
    const std::string& bytes_;
    const std::string& path_;
    std::size_t at_ = 0;
};

}  // namespace

void writeCheckpoint(const std::string& path, const SolverState& state, std::uint64_t fingerprint) {
    Writer w;
    w.bytes.append(kMagic, sizeof kMagic);
    w.put(kVersion);
    w.put(fingerprint);
    w.put(static_cast<std::uint64_t>(state.incident.size()));
    w.put(static_cast<std::uint64_t>(state.unshot.size()));
    w.put(static_cast<std::uint64_t>(state.caustic.size()));
    w.put(state.tallies.shots);
    w.put(state.tallies.rays);
    w.put(state.tallies.batches);
    w.put(state.seconds);
    for (int c = 0; c < 3; ++c) w.put(state.escaped[c]);
    for (int c = 0; c < 3; ++c) w.put(state.absorbedByBacks[c]);
    for (int c = 0; c < 3; ++c) w.put(state.shot[c]);
    w.putArray(state.incident);
    w.putArray(state.unshot);
    w.putArray(state.samplesUsed);
    w.putArray(state.caustic);
    w.put(Fnv1a().add(w.bytes.data(), w.bytes.size()).value());
    writeFileAtomically(path, [&](std::ostream& out) { out.write(w.bytes.data(), static_cast<std::streamsize>(w.bytes.size())); });
}

SolverState readCheckpoint(const std::string& path, std::uint64_t fingerprint) {
    std::ifstream in(path, std::ios::binary);
    if (!in) throw FileError(path, "cannot open the checkpoint");
    const std::string bytes((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
    if (bytes.size() < sizeof kMagic + 8 || std::memcmp(bytes.data(), kMagic, sizeof kMagic) != 0)
        throw FileError(path, "not a radiosity checkpoint");
    std::uint64_t stored;
    std::memcpy(&stored, bytes.data() + bytes.size() - 8, 8);
    if (Fnv1a().add(bytes.data(), bytes.size() - 8).value() != stored)
        throw FileError(path, "the checkpoint is damaged (its checksum does not match)");
    Reader r(bytes, path);
    r.get<std::array<char, sizeof kMagic>>();
    const auto version = r.get<std::uint32_t>();
    if (version != kVersion)
        throw FileError(path, "checkpoint format " + std::to_string(version) + " is not this program's (" +
                                  std::to_string(kVersion) + ")");
    if (r.get<std::uint64_t>() != fingerprint)
        throw FileError(path, "the checkpoint belongs to another problem (scene, patch size, seed or solver options differ)");
    SolverState state;
    const auto elements = r.get<std::uint64_t>(), patches = r.get<std::uint64_t>();
    const auto caustic = r.get<std::uint64_t>();
    if (elements > bytes.size() || patches > bytes.size() || caustic > bytes.size())
        throw FileError(path, "the checkpoint is truncated");
    state.tallies.shots = r.get<std::uint64_t>();
    state.tallies.rays = r.get<std::uint64_t>();
    state.tallies.batches = r.get<std::uint64_t>();
    state.seconds = r.get<double>();
    for (int c = 0; c < 3; ++c) state.escaped[c] = r.get<double>();
    for (int c = 0; c < 3; ++c) state.absorbedByBacks[c] = r.get<double>();
    for (int c = 0; c < 3; ++c) state.shot[c] = r.get<double>();
    r.getArray(state.incident, elements);
    r.getArray(state.unshot, patches);
    r.getArray(state.samplesUsed, patches);
    r.getArray(state.caustic, caustic);
    return state;
}

}  // namespace rad
