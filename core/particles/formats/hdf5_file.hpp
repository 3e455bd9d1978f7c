// An HDF5 file opened for reading through libhdf5's C API (its own error printing switched
// off): handles closed by their own close functions, every external link and virtual
// dataset followed only to a regular file that exists, and each such file an input that no
// output may replace. Shared by the readers of snapshots and of PySPH files.
#pragma once

#include "particles/particle_set.hpp"
#include "particles/particles_memory.hpp"
#include "support/error.hpp"
#include "support/text/printable_text.hpp"
#include "support/text/setting_names.hpp"

#include <fmt/format.h>
#include <hdf5.h>

#include <sys/stat.h>

#include <algorithm>
#include <cstdlib>
#include <filesystem>
#include <string>
#include <vector>

namespace sphkern::hdf5 {

void silence_hdf5();

extern "C" herr_t follow_external_link(const char*, const char* group, const char* child_file, const char* child_object,
                                       unsigned*, hid_t, void* data);

// An HDF5 handle closed by its own close function.
class Handle {
public:
    Handle(hid_t id, herr_t (*close)(hid_t)) : id_(id), close_(close) {}
    ~Handle()
    {
        if (id_ >= 0) close_(id_);
    }
    Handle(Handle&& other) noexcept : id_(other.id_), close_(other.close_) { other.id_ = -1; }
    Handle(const Handle&) = delete;
    Handle& operator=(const Handle&) = delete;
    hid_t get() const { return id_; }
    bool valid() const { return id_ >= 0; }

private:
    hid_t id_;
    herr_t (*close_)(hid_t);
};

// The files an HDF5 file reaches through external links and virtual datasets. Each is followed
// only to a regular file that exists (an open of a FIFO or a device would block, a missing part
// would read as fill values), and each is an input that no output may replace.
struct LinkedFiles {
    std::filesystem::path folder; // of the file read: relative names start there
    std::vector<std::string> files;
    std::string refusal; // why a link was not followed

    // `name` as libhdf5 looks for it: as given, under the prefixes of `prefix_variable`, beside the file.
    bool admit(const std::string& name, const char* prefix_variable, const std::string& what)
    {
        const std::filesystem::path given(name);
        std::vector<std::filesystem::path> places{given};
        if (given.is_relative()) {
            if (const char* prefixes = std::getenv(prefix_variable)) {
                std::string list = prefixes;
                for (std::size_t start = 0, end; start <= list.size(); start = end + 1) {
                    end = std::min(list.find(':', start), list.size());
                    if (end > start) places.push_back(std::filesystem::path(list.substr(start, end - start)) / given);
                }
            }
            places.push_back(folder / given);
        }
        bool found = false;
        for (const auto& place : places) {
            struct stat status {};
            if (::stat(place.c_str(), &status) != 0) continue;
            if (!S_ISREG(status.st_mode)) {
                refusal = fmt::format("{} leads to {}, which is not a regular file", what, place.string());
                return false;
            }
            files.push_back(place.lexically_normal().string());
            found = true;
        }
        if (!found) refusal = fmt::format("{} leads to {}, which does not exist", what, name);
        return found;
    }
};

struct File {
    std::string name;
    hid_t id;
    LinkedFiles* linked;
    // Link, dataset and group access, each following external links through follow_external_link.
    hid_t links, dataset_access, group_access;

    // Every lookup goes through here: a link that was refused is the error, not its symptom.
    void check_links() const
    {
        if (!linked->refusal.empty()) fail_input(fmt::format("{}: {}", name, linked->refusal));
    }
    bool exists(const std::string& path) const
    {
        const bool found = H5Lexists(id, path.c_str(), links) > 0;
        check_links();
        return found;
    }
    // A virtual dataset's source files, followed like external links; values stored outside the file refused.
    void check_sources(hid_t set, const std::string& path) const
    {
        Handle create(H5Dget_create_plist(set), H5Pclose);
        if (H5Pget_external_count(create.get()) > 0)
            fail_input(fmt::format("{}: dataset {} keeps its values in external raw files; expected them in the "
                                   "HDF5 file or a virtual dataset",
                                   name, path));
        if (H5Pget_layout(create.get()) != H5D_VIRTUAL) return;
        std::size_t count = 0;
        H5Pget_virtual_count(create.get(), &count);
        for (std::size_t i = 0; i < count; ++i) {
            const ssize_t length = H5Pget_virtual_filename(create.get(), i, nullptr, 0);
            std::string source(static_cast<std::size_t>(std::max<ssize_t>(length, 0)) + 1, '\0');
            H5Pget_virtual_filename(create.get(), i, source.data(), source.size());
            source.resize(static_cast<std::size_t>(std::max<ssize_t>(length, 0)));
            if (source == ".") continue; // the file itself
            linked->admit(source, "HDF5_VDS_PREFIX", fmt::format("the virtual dataset {} maps {}", path, source));
            check_links();
        }
    }

    // The shape a dataset declares (rank 1 or 2), nothing read.
    std::vector<hsize_t> shape(const std::string& path) const
    {
        Handle set(H5Dopen2(id, path.c_str(), dataset_access), H5Dclose);
        check_links();
        if (!set.valid()) fail_input(fmt::format("{}: dataset {} cannot be opened", name, path));
        check_sources(set.get(), path); // the files it maps are inputs from now on
        // What its values are comes before how many: a table of records (a compound type) is not numbers.
        Handle type(H5Dget_type(set.get()), H5Tclose);
        const H5T_class_t kind = H5Tget_class(type.get());
        if (kind != H5T_FLOAT && kind != H5T_INTEGER)
            fail_input(
                fmt::format("{}: dataset {} does not hold numbers (its values are {}); expected integers or floats",
                            name, path, kind == H5T_COMPOUND ? "records of several fields" : "not numbers"));
        Handle space(H5Dget_space(set.get()), H5Sclose);
        const int rank = H5Sget_simple_extent_ndims(space.get());
        if (rank < 1 || rank > 2) fail_input(fmt::format("{}: dataset {} is not a table of rows", name, path));
        std::vector<hsize_t> dims(static_cast<std::size_t>(rank), 0);
        H5Sget_simple_extent_dims(space.get(), dims.data(), nullptr);
        return dims;
    }
    std::size_t rows(const std::string& path) const { return static_cast<std::size_t>(shape(path)[0]); }
    // A dataset of doubles (any stored number type is converted) with its shape.
    // A dataset of numbers, opened: its links and sources followed, another stored type refused.
    Handle open_numbers(const std::string& path) const
    {
        Handle set(H5Dopen2(id, path.c_str(), dataset_access), H5Dclose);
        check_links();
        if (!set.valid()) fail_input(fmt::format("{}: dataset {} cannot be opened", name, path));
        check_sources(set.get(), path);
        Handle type(H5Dget_type(set.get()), H5Tclose);
        const H5T_class_t kind = H5Tget_class(type.get());
        if (kind != H5T_FLOAT && kind != H5T_INTEGER)
            fail_input(fmt::format("{}: dataset {} does not hold numbers", name, path));
        return set;
    }
    // Reads the selection `space` of `set` into `values` (memory laid out as `memory`).
    void read_numbers(const Handle& set, hid_t memory, hid_t space, ParticleValues& values,
                      const std::string& path) const
    {
        if (!values.empty() && H5Dread(set.get(), H5T_NATIVE_DOUBLE, memory, space, H5P_DEFAULT, values.data()) < 0)
            fail_input(fmt::format("{}: dataset {} cannot be read (a truncated file?)", name, path));
    }
    ParticleValues dataset(const std::string& path, std::vector<hsize_t>& shape) const
    {
        const Handle set = open_numbers(path);
        Handle space(H5Dget_space(set.get()), H5Sclose);
        const int rank = H5Sget_simple_extent_ndims(space.get());
        if (rank < 1 || rank > 2)
            fail_input(fmt::format("{}: dataset {} has rank {}; expected 1 or 2", name, path, rank));
        shape.assign(static_cast<std::size_t>(rank), 0);
        H5Sget_simple_extent_dims(space.get(), shape.data(), nullptr);
        // A declared size is checked against the budget before anything is allocated for it.
        double total = 1;
        for (auto s : shape) total *= static_cast<double>(s);
        if (static_cast<double>(shape[0]) > static_cast<double>(max_particles()) ||
            total * sizeof(double) > static_cast<double>(particle_file_byte_limit()))
            fail_input(fmt::format("{}: dataset {} declares {} rows ({:.4g} bytes to read, {:.4g} bytes for the "
                                   "particles); over the {:.4g} bytes a file's values may take of the memory budget of "
                                   "{:.4g} bytes ({})",
                                   name, path, shape[0], total * sizeof(double),
                                   static_cast<double>(shape[0]) * bytes_per_particle,
                                   static_cast<double>(particle_file_byte_limit()),
                                   static_cast<double>(memory_limit_bytes()), setting_named("memory_limit")));
        ParticleValues values(static_cast<std::size_t>(total));
        read_numbers(set, H5S_ALL, H5S_ALL, values, path);
        return values;
    }
    // Rows [begin, begin + count) of a table of numbers (any stored number type, as doubles),
    // `columns` a row: a hyperslab, so that a file larger than memory is read a part at a time.
    ParticleValues row_range(const std::string& path, std::size_t begin, std::size_t count, std::size_t columns) const
    {
        const Handle set = open_numbers(path);
        Handle space(H5Dget_space(set.get()), H5Sclose);
        const int rank = H5Sget_simple_extent_ndims(space.get());
        const hsize_t start[2] = {begin, 0}, extent[2] = {count, columns};
        if (H5Sselect_hyperslab(space.get(), H5S_SELECT_SET, start, nullptr, extent, nullptr) < 0)
            fail_input(
                fmt::format("{}: rows {} to {} of dataset {} cannot be selected", name, begin, begin + count, path));
        Handle memory(H5Screate_simple(rank, extent, nullptr), H5Sclose);
        ParticleValues values(count * columns);
        read_numbers(set, memory.get(), space.get(), values, path);
        return values;
    }
    ParticleValues column(const std::string& path, std::size_t count) const
    {
        std::vector<hsize_t> shape;
        auto values = dataset(path, shape);
        if (!(shape.size() == 1 || (shape.size() == 2 && shape[1] == 1)) || shape[0] != count)
            fail_input(fmt::format("{}: dataset {} has shape {}; expected ({}) or ({}, 1)", name, path,
                                   shape_text(shape), count, count));
        return values;
    }
    // A numeric attribute of `object` with up to `max` values.
    std::vector<double> attribute(const std::string& object, const std::string& attr) const
    {
        if (!exists(object) || H5Aexists_by_name(id, object.c_str(), attr.c_str(), links) <= 0) return {};
        Handle a(H5Aopen_by_name(id, object.c_str(), attr.c_str(), H5P_DEFAULT, links), H5Aclose);
        check_links();
        Handle space(H5Aget_space(a.get()), H5Sclose);
        const hssize_t n = H5Sget_simple_extent_npoints(space.get());
        Handle type(H5Aget_type(a.get()), H5Tclose);
        const H5T_class_t kind = H5Tget_class(type.get());
        if (n <= 0 || n > 64 || (kind != H5T_FLOAT && kind != H5T_INTEGER))
            fail_input(fmt::format("{}: attribute {} of {} is not a short list of numbers", name, attr, object));
        std::vector<double> values(static_cast<std::size_t>(n));
        if (H5Aread(a.get(), H5T_NATIVE_DOUBLE, values.data()) < 0)
            fail_input(fmt::format("{}: attribute {} of {} cannot be read", name, attr, object));
        return values;
    }
    // A text attribute of `object` (fixed or variable length), "" when there is none.
    std::string text_attribute(const std::string& object, const std::string& attr) const
    {
        if (!exists(object) || H5Aexists_by_name(id, object.c_str(), attr.c_str(), links) <= 0) return {};
        Handle a(H5Aopen_by_name(id, object.c_str(), attr.c_str(), H5P_DEFAULT, links), H5Aclose);
        check_links();
        Handle type(H5Aget_type(a.get()), H5Tclose);
        Handle space(H5Aget_space(a.get()), H5Sclose);
        if (H5Tget_class(type.get()) != H5T_STRING || H5Sget_simple_extent_npoints(space.get()) != 1) return {};
        std::string text;
        if (H5Tis_variable_str(type.get()) > 0) {
            char* value = nullptr;
            Handle memory(H5Tcopy(H5T_C_S1), H5Tclose);
            H5Tset_size(memory.get(), H5T_VARIABLE);
            // h5py writes UTF-8 (its default for str): read in the file's character set, or HDF5 refuses to convert.
            H5Tset_cset(memory.get(), H5Tget_cset(type.get()));
            if (H5Aread(a.get(), memory.get(), &value) >= 0 && value) text = value;
            if (value) H5free_memory(value);
        } else {
            const std::size_t size = H5Tget_size(type.get());
            if (size == 0 || size > 4096) return {};
            std::string buffer(size, '\0');
            if (H5Aread(a.get(), type.get(), buffer.data()) >= 0) text = buffer.c_str();
        }
        return printable_text(text);
    }
    static std::string shape_text(const std::vector<hsize_t>& shape)
    {
        std::string text;
        for (auto s : shape) text += (text.empty() ? "" : ", ") + std::to_string(s);
        return "(" + text + ")";
    }
};

// An HDF5 file opened for reading, every link followed through follow_external_link.
class OpenFile {
public:
    explicit OpenFile(const std::filesystem::path& file)
        : linked_{std::filesystem::absolute(file).parent_path(), {}, {}}, handle_(open(file), H5Fclose),
          links_(H5Pcreate(H5P_LINK_ACCESS), H5Pclose), dataset_access_(H5Pcreate(H5P_DATASET_ACCESS), H5Pclose),
          group_access_(H5Pcreate(H5P_GROUP_ACCESS), H5Pclose),
          file_{file.string(), handle_.get(), &linked_, links_.get(), dataset_access_.get(), group_access_.get()}
    {
        for (hid_t list : {links_.get(), dataset_access_.get(), group_access_.get()})
            H5Pset_elink_cb(list, follow_external_link, &linked_);
    }
    const File& file() const { return file_; }
    const std::vector<std::string>& linked_files() const { return linked_.files; }

private:
    static hid_t open(const std::filesystem::path& file)
    {
        const std::string name = file.string();
        std::error_code ec;
        if (!std::filesystem::is_regular_file(file, ec)) fail_input(name + ": no such file");
        if (H5Fis_hdf5(file.c_str()) <= 0) fail_input(name + ": not an HDF5 file");
        const hid_t id = H5Fopen(file.c_str(), H5F_ACC_RDONLY, H5P_DEFAULT);
        if (id < 0) fail_input(name + ": cannot be opened as HDF5 (a truncated file?)");
        return id;
    }
    LinkedFiles linked_;
    Handle handle_, links_, dataset_access_, group_access_;
    File file_;
};

} // namespace sphkern::hdf5
