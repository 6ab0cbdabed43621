// distributed_plan_file.hpp: a distributed plan's parts in one file.
#include "dgwarp/mpi/distributed_plan_file.hpp"

#include <array>
#include <cerrno>
#include <cstring>
#include <exception>
#include <fstream>
#include <string>
#include <vector>

#include "dgwarp/core/atomic_write.hpp"
#include "dgwarp/core/error.hpp"
#include "dgwarp/core/hash.hpp"
#include "dgwarp/methods/option_table.hpp"
#include "dgwarp/plan/plan_file.hpp"
#include "dgwarp/mpi/large_transfers.hpp"

namespace dgwarp::mpi {

namespace {

constexpr std::array<char, 8> magic = {'D', 'G', 'W', 'D', 'I', 'S', 'T', '\0'};
constexpr std::uint32_t version = 1;
constexpr int part_tag = 7301;

/// Throws ParseError (through `r`) when an index array of the part points
/// outside what it indexes (a file that passed its checksum but was written
/// by something else than save_distributed_plan).
void check_part(const DistributedPlan& p, std::size_t local_boundary, const auto& fail) {
    const auto working = static_cast<std::int64_t>(p.num_working_points());
    const auto in = [](const auto& v, std::int64_t hi) {
        for (auto x : v)
            if (x < 0 || x >= hi) return false;
        return true;
    };
    const auto sum = [](const std::vector<int>& v) {
        std::int64_t s = 0;
        for (int x : v) s += x;
        return s;
    };
    if (p.dim != 2 && p.dim != 3) fail("dimension 2 or 3", std::to_string(p.dim));
    if (p.working_points.size() % static_cast<std::size_t>(p.dim) != 0) fail("whole working points", "a remainder");
    if (p.local_to_working.size() != static_cast<std::size_t>(p.num_local_points) || !in(p.local_to_working, working))
        fail("a working node per local node", "other indices");
    if (p.local_boundary_index.size() != local_boundary || !in(p.local_boundary_index, working) ||
        !in(p.adopted_boundary, working) || !in(p.owned_boundary, working) || !in(p.recv_boundary, working))
        fail("working boundary indices", "others");
    if (!in(p.my_owned_local, static_cast<std::int64_t>(local_boundary)) ||
        !in(p.send_local, static_cast<std::int64_t>(local_boundary)))
        fail("local boundary indices", "others");
    const auto size = static_cast<std::size_t>(p.size);
    if ((p.gather_all && (p.owned_counts.size() != size || sum(p.owned_counts) != static_cast<std::int64_t>(p.owned_boundary.size()))) ||
        (!p.gather_all && (p.send_counts.size() != size || p.recv_counts.size() != size ||
                           sum(p.send_counts) != static_cast<std::int64_t>(p.send_local.size()) ||
                           sum(p.recv_counts) != static_cast<std::int64_t>(p.recv_boundary.size()))))
        fail("exchange counts that add up", "others");
    if (p.counted_shared_offsets.empty() || p.counted_shared_offsets.front() != 0 ||
        p.counted_shared_offsets.back() != static_cast<std::int32_t>(p.counted_shared_members.size()) ||
        !in(p.counted_shared_members, working))
        fail("shared vertex groups", "others");
}

template <class T>
void put(std::vector<std::byte>& out, const T& v) {
    const auto* p = reinterpret_cast<const std::byte*>(&v);
    out.insert(out.end(), p, p + sizeof v);
}
template <class T>
void put_array(std::vector<std::byte>& out, const std::vector<T>& v) {
    put(out, static_cast<std::uint64_t>(v.size()));
    const auto bytes = std::as_bytes(std::span(v));
    out.insert(out.end(), bytes.begin(), bytes.end());
}

/// Reads fields from bytes, with bounds checked (ParseError naming `name` and the offset).
struct Reader {
    std::span<const std::byte> bytes;
    std::string name;
    std::size_t at = 0;
    std::size_t base = 0;  // the part's offset in the file, for messages

    [[noreturn]] void fail(const std::string& expected, const std::string& found) const {
        throw ParseError(name, base + at, expected, found);
    }
    template <class T>
    T get(const char* what) {
        if (bytes.size() - at < sizeof(T)) fail(what, "the end of the part");
        T v;
        std::memcpy(&v, bytes.data() + at, sizeof v);
        at += sizeof v;
        return v;
    }
    template <class T>
    std::vector<T> get_array(const char* what) {
        const auto n = get<std::uint64_t>(what);
        if (n > (bytes.size() - at) / sizeof(T)) fail(std::string(what) + " within the part", std::to_string(n) + " values");
        std::vector<T> v(static_cast<std::size_t>(n));
        if (n > 0) std::memcpy(v.data(), bytes.data() + at, static_cast<std::size_t>(n) * sizeof(T));
        at += static_cast<std::size_t>(n) * sizeof(T);
        return v;
    }
};

std::vector<std::byte> part_bytes(const DistributedPlan& p, std::uint64_t hash) {
    std::vector<std::byte> out;
    put(out, static_cast<std::int32_t>(p.rank));
    put(out, static_cast<std::int32_t>(p.method));
    put(out, static_cast<std::int32_t>(p.dim));
    put(out, static_cast<std::int64_t>(p.num_local_points));
    put(out, static_cast<std::int64_t>(p.num_boundary_nodes));
    put(out, static_cast<std::int64_t>(p.num_coarse_points));
    put(out, static_cast<std::uint8_t>(p.gather_all ? 1 : 0));
    put(out, hash);
    put_array(out, p.working_points);
    put_array(out, p.local_to_working);
    put_array(out, p.local_boundary_index);
    put_array(out, p.adopted_boundary);
    put_array(out, p.owned_counts);
    put_array(out, p.owned_boundary);
    put_array(out, p.my_owned_local);
    put_array(out, p.send_counts);
    put_array(out, p.recv_counts);
    put_array(out, p.send_local);
    put_array(out, p.recv_boundary);
    put_array(out, p.counted_shared_offsets);
    put_array(out, p.counted_shared_members);
    put_array(out, plan_file_bytes(p.plan));
    return out;
}

/// A failure on any process, raised on every process: the failing process
/// rethrows its own exception, the others an Error naming the lowest failing
/// process and its message.
void agree(MPI_Comm comm, const std::exception_ptr& error, const std::string& what) {
    int rank = 0, size = 1;
    MPI_Comm_rank(comm, &rank);
    MPI_Comm_size(comm, &size);
    std::string message;
    if (error) {
        try {
            std::rethrow_exception(error);
        } catch (const std::exception& e) {
            message = e.what();
        }
    }
    int mine = error ? rank : size, first = size;
    MPI_Allreduce(&mine, &first, 1, MPI_INT, MPI_MIN, comm);
    if (first == size) return;
    int length = static_cast<int>(std::min<std::size_t>(message.size(), 4096));
    MPI_Bcast(&length, 1, MPI_INT, first, comm);
    message.resize(static_cast<std::size_t>(length));
    MPI_Bcast(message.data(), length, MPI_CHAR, first, comm);
    if (error) std::rethrow_exception(error);
    throw Error("process " + std::to_string(first) + " failed " + what + ": " + message);
}

}  // namespace

std::uint64_t distributed_inputs_hash(std::span<const double> points, std::span<const std::int64_t> global_ids,
                                      const BoundarySet& boundary) {
    std::uint64_t h = hash64_of(points);
    h = hash64_of(global_ids, h);
    h = hash64_of(std::span<const NodeId>(boundary.nodes), h);
    return hash64_of(std::span<const std::uint8_t>(boundary.moving), h);
}

void save_distributed_plan(const std::filesystem::path& path, const DistributedPlan& plan) {
    // Every process refuses the same way (they share the method): no collective call is left hanging.
    if (!plan_can_be_saved(plan.plan))
        throw Error(std::string("distributed plans of ") + std::string(method_name(plan.method)) +
                    " cannot be saved (only dg-idw and dg-harmonic plans can)");
    std::exception_ptr error;
    std::vector<std::byte> mine;
    try {
        mine = part_bytes(plan, plan.input_hash);
    } catch (...) {
        error = std::current_exception();
    }
    agree(plan.comm, error, "to serialise its part of the plan");
    if (plan.rank != 0) {
        detail::send_bytes(plan.comm, mine, 0, part_tag);
    } else {
        try {
            std::vector<std::vector<std::byte>> parts(static_cast<std::size_t>(plan.size));
            parts[0] = std::move(mine);
            for (int r = 1; r < plan.size; ++r) parts[static_cast<std::size_t>(r)] = detail::receive_bytes(plan.comm, r, part_tag);
            write_file_atomically(path, [&](std::ostream& out) {
                std::vector<std::byte> header(magic.size());
                std::memcpy(header.data(), magic.data(), magic.size());
                put(header, version);
                put(header, static_cast<std::uint32_t>(plan.size));
                out.write(reinterpret_cast<const char*>(header.data()), static_cast<std::streamsize>(header.size()));
                std::uint64_t checksum = hash64(header);
                for (const auto& part : parts) {
                    const auto length = static_cast<std::uint64_t>(part.size());
                    out.write(reinterpret_cast<const char*>(&length), sizeof length);
                    out.write(reinterpret_cast<const char*>(part.data()), static_cast<std::streamsize>(part.size()));
                    checksum = hash64(std::as_bytes(std::span(&length, 1)), checksum);
                    checksum = hash64(part, checksum);
                }
                out.write(reinterpret_cast<const char*>(&checksum), sizeof checksum);
            });
        } catch (...) {
            error = std::current_exception();
        }
    }
    agree(plan.comm, error, "to write " + path.string());
}

DistributedPlan load_distributed_plan(MPI_Comm comm, const std::filesystem::path& path,
                                      std::span<const double> points, std::span<const std::int64_t> global_ids,
                                      const BoundarySet& boundary) {
    int rank = 0, size = 1;
    MPI_Comm_rank(comm, &rank);
    MPI_Comm_size(comm, &size);
    const std::string name = path.string();
    // Process 0 reads and checks the whole file, then sends each process its part.
    std::exception_ptr error;
    std::vector<std::vector<std::byte>> parts;
    std::vector<std::size_t> offsets;
    if (rank == 0) {
        try {
            std::ifstream in(path, std::ios::binary);
            if (!in) throw IoError(name, "cannot open the plan file", errno);
            const std::vector<char> raw((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
            const std::span<const std::byte> bytes(reinterpret_cast<const std::byte*>(raw.data()), raw.size());
            Reader r{bytes, name};
            if (bytes.size() < magic.size() || std::memcmp(bytes.data(), magic.data(), magic.size()) != 0)
                r.fail("a distributed plan file (magic DGWDIST)", "other bytes");
            r.at = magic.size();
            const auto v = r.get<std::uint32_t>("the format version");
            if (v != version) {
                r.at -= sizeof v;
                r.fail("format version " + std::to_string(version), std::to_string(v));
            }
            const auto processes = r.get<std::uint32_t>("the number of processes");
            if (processes != static_cast<std::uint32_t>(size)) {
                r.at -= sizeof processes;
                r.fail("a plan for " + std::to_string(size) + " processes (this run's)",
                       "one for " + std::to_string(processes) + ": prepare again, or run with as many processes");
            }
            std::uint64_t checksum = hash64(bytes.first(r.at));
            for (std::uint32_t p = 0; p < processes; ++p) {
                const std::size_t length_at = r.at;
                const auto length = r.get<std::uint64_t>("a part's length");
                if (length > bytes.size() - r.at) {
                    r.at = length_at;
                    r.fail("a part within the file", std::to_string(length) + " bytes");
                }
                checksum = hash64(bytes.subspan(length_at, sizeof length), checksum);
                offsets.push_back(r.at);
                parts.emplace_back(bytes.begin() + static_cast<std::ptrdiff_t>(r.at),
                                   bytes.begin() + static_cast<std::ptrdiff_t>(r.at + length));
                checksum = hash64(parts.back(), checksum);
                r.at += static_cast<std::size_t>(length);
            }
            const auto stored = r.get<std::uint64_t>("the checksum");
            if (r.at != bytes.size()) r.fail("the end of the file after the checksum", "more bytes");
            if (stored != checksum) {
                r.at -= sizeof stored;
                r.fail("the file's checksum", "another: the file is damaged");
            }
        } catch (...) {
            error = std::current_exception();
        }
    }
    agree(comm, error, "to read " + name);
    std::vector<std::byte> mine;
    std::size_t base = 0;
    if (rank == 0) {
        for (int p = 1; p < size; ++p) detail::send_bytes(comm, parts[static_cast<std::size_t>(p)], p, part_tag);
        mine = std::move(parts[0]);
        base = offsets[0];
    } else {
        mine = detail::receive_bytes(comm, 0, part_tag);
    }
    // Each process: its part, checked against its inputs.
    DistributedPlan plan;
    try {
        Reader r{mine, name + " (process " + std::to_string(rank) + "'s part)", 0, base};
        plan.comm = comm;
        plan.rank = rank;
        plan.size = size;
        if (r.get<std::int32_t>("the part's rank") != rank) r.fail("process " + std::to_string(rank) + "'s part", "another's");
        plan.method = static_cast<Method>(r.get<std::int32_t>("the method"));
        plan.dim = r.get<std::int32_t>("the dimension");
        plan.num_local_points = r.get<std::int64_t>("the local point count");
        plan.num_boundary_nodes = r.get<std::int64_t>("the boundary node count");
        plan.num_coarse_points = r.get<std::int64_t>("the coarse point count");
        plan.gather_all = r.get<std::uint8_t>("the exchange kind") != 0;
        plan.input_hash = r.get<std::uint64_t>("the inputs' hash");
        if (plan.dim * plan.num_local_points != static_cast<std::int64_t>(points.size()) ||
            plan.num_local_points != static_cast<std::int64_t>(global_ids.size()) ||
            plan.input_hash != distributed_inputs_hash(points, global_ids, boundary))
            throw MeshError("the distributed plan " + name + " was prepared for other points, global ids or "
                            "boundary nodes on process " + std::to_string(rank) +
                            " (a plan keeps the partition it was made for)");
        plan.working_points = r.get_array<double>("the working points");
        plan.local_to_working = r.get_array<std::int32_t>("local_to_working");
        plan.local_boundary_index = r.get_array<std::int32_t>("local_boundary_index");
        plan.adopted_boundary = r.get_array<std::int32_t>("adopted_boundary");
        plan.owned_counts = r.get_array<int>("owned_counts");
        plan.owned_boundary = r.get_array<std::int32_t>("owned_boundary");
        plan.my_owned_local = r.get_array<std::int32_t>("my_owned_local");
        plan.send_counts = r.get_array<int>("send_counts");
        plan.recv_counts = r.get_array<int>("recv_counts");
        plan.send_local = r.get_array<std::int32_t>("send_local");
        plan.recv_boundary = r.get_array<std::int32_t>("recv_boundary");
        plan.counted_shared_offsets = r.get_array<std::int32_t>("counted_shared_offsets");
        plan.counted_shared_members = r.get_array<std::int32_t>("counted_shared_members");
        const std::vector<std::byte> method_plan = r.get_array<std::byte>("the method's plan");
        if (r.at != mine.size()) r.fail("the end of the part", "more bytes");
        plan.plan = load_plan_bytes(method_plan, name + " (process " + std::to_string(rank) + "'s method plan)");
        if (plan_method(plan.plan) != plan.method) r.fail("a method plan of the part's method", "another method's");
        plan.options = options_with_plan(plan.plan, plan.options);
        check_part(plan, boundary.nodes.size(), [&](const std::string& e, const std::string& f) { r.fail(e, f); });
    } catch (...) {
        error = std::current_exception();
    }
    agree(comm, error, "to load its part of " + name);
    return plan;
}

}  // namespace dgwarp::mpi
