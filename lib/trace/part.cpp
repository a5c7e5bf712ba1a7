// The provenance items of a part of a render: rows, tile, input digest, options.
#include "trace/part.hpp"

#include <filesystem>

#include "core/digest.hpp"
#include "core/text.hpp"
#include "image/merge.hpp"
#include "io/mat.hpp"
#include "io/odb.hpp"

namespace sigchain::trace {

namespace {

// As radiometry's materials resolve a file the .mat names: against the .mat's folder.
std::string beside(const std::string& mat_path, const std::string& file) {
    std::filesystem::path p(file);
    if (p.is_absolute() || mat_path.empty() || mat_path == "-") return file;
    return (std::filesystem::path(mat_path).parent_path() / p).string();
}

}  // namespace

std::vector<std::string> input_files(const TraceJob& job) {
    std::vector<std::string> files{job.adv_path, job.snd_path, job.scene_path, job.mat_path};
    files.insert(files.end(), job.rad_paths.begin(), job.rad_paths.end());
    for (const std::string* f : {&job.tmp_path, &job.scene_input.material_map,
                                 &job.scene_input.landuse, &job.scene_input.landuse_map})
        if (!f->empty()) files.push_back(*f);
    for (const io::Material& m : io::read_mat_file(job.mat_path).materials)
        for (const std::string* f :
             {&m.emissivity_file, &m.extinction_file, &m.texture_file, &m.table_file})
            if (!f->empty()) files.push_back(beside(job.mat_path, *f));
    if (file_extension(job.scene_path) == "odb") {
        const io::Odb odb = io::read_odb_file(job.scene_path);
        for (const io::OdbObject& object : odb.objects)
            for (const std::string* f : {&object.path, &object.material_map,
                                         &object.landuse_file, &object.landuse_map})
                if (!f->empty()) files.push_back(io::resolve_odb_path(odb, *f));
    }
    std::vector<std::string> present;
    for (const std::string& f : files)
        if (std::filesystem::is_regular_file(f)) present.push_back(f);
    return present;
}

image::WriteOptions part_write_options(const TraceJob& job, long row_begin, long row_end,
                                       long rows) {
    image::WriteOptions options = job.write_options;
    if (row_begin == 0 && row_end == rows) return options;
    options.items.emplace_back("rows", image::part_rows_text({row_begin, row_end, rows}));
    if (job.tile) options.items.emplace_back("tile", job.tile->text());
    options.items.emplace_back("inputs", sha256_files(input_files(job)));
    options.items.emplace_back("options", job.part_options);
    return options;
}

}  // namespace sigchain::trace
