// Registry of file formats by extension: one line per format below.
#include "io/registry.hpp"

#include <algorithm>

// FORMAT HEADERS (one include per format)
#include "io/adv.hpp"
#include "io/brdf.hpp"
#include "io/cdk.hpp"
#include "io/cpt.hpp"
#include "io/ems.hpp"
#include "io/ext.hpp"
#include "io/gdb.hpp"
#include "io/mat.hpp"
#include "io/mtl.hpp"
#include "io/odb.hpp"
#include "io/rad.hpp"
#include "io/rsd.hpp"
#include "io/rsr.hpp"
#include "io/sen.hpp"
#include "io/shd.hpp"
#include "io/snd.hpp"
#include "io/t7m.hpp"
#include "io/tmp.hpp"
#include "io/trj.hpp"
#include "io/unc.hpp"
#include "io/wth.hpp"

namespace sigchain::io {

const std::vector<FormatHandler>& formats() {
    // clang-format off
    static const std::vector<FormatHandler> all = [] {
        std::vector<FormatHandler> v = {
            // FORMAT LIST (one line per format: X_format(),)
            adv_format(),
            brdf_format(),
            cdk_format(),
            cpt_format(),
            ems_format(),
            ext_format(),
            gdb_format(),
            mat_format(),
            mtl_format(),
            odb_format(),
            rad_format(),
            rsd_format(),
            rsr_format(),
            sen_format(),
            shd_format(),
            snd_format(),
            t7m_format(),
            tmp_format(),
            trj_format(),
            unc_format(),
            wth_format(),
        };
        // clang-format on
        std::sort(v.begin(), v.end(),
                  [](const auto& a, const auto& b) { return a.extension < b.extension; });
        return v;
    }();
    return all;
}

const FormatHandler* find_format(std::string_view extension) {
    for (const auto& f : formats())
        if (f.extension == extension) return &f;
    return nullptr;
}

}  // namespace sigchain::io
