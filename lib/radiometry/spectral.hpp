// The spectral grid of a render: every spectral sample of every band, in band order
// (the order of the .rad files given to trace), each band's samples in increasing
// wavelength (the .rad's order). One geometry pass serves all of them.
#pragma once

#include <string>
#include <vector>

namespace sigchain::radiometry {

struct SpectralGrid {
    std::vector<double> wavelength_um;  // one per sample, per band increasing
    std::vector<int> band_of_sample;    // 0-based band index of each sample
    std::vector<std::string> band_names;  // one per band (the .rad file's stem)
    std::size_t size() const { return wavelength_um.size(); }
    std::size_t band_count() const { return band_names.size(); }
    // Index of the sample nearest the centre wavelength of band `band` (truth layers).
    std::size_t band_centre_sample(int band) const;
};

}  // namespace sigchain::radiometry
