// How linear render results become file values: POV-Ray 3.7's gamma
// rules (assumed_gamma, File_Gamma, the pre-3.7 compatibility mode).
#pragma once

namespace frameray::image {

class GammaEncoding {
  public:
    enum class Curve { Identity, Power, SRGB };

    // The 3.7 rules: a scene with assumed_gamma works in that gamma and the
    // file is encoded with File_Gamma (sRGB unless set); a scene without it
    // that declares #version 3.7 or later is linear (assumed_gamma 1); an
    // older scene without it has gamma handling turned off.
    // `fileGamma` <= 0 means sRGB.
    static GammaEncoding forScene(bool assumedGammaSet, double assumedGamma, double languageVersion,
                                  double fileGamma);

    // File values equal working values (no gamma handling).
    static GammaEncoding identity() {
        GammaEncoding g;
        g.curve_ = Curve::Identity;
        return g;
    }

    // Maps a working-space value in [0,1] (already clipped) to [0,1] file space.
    double encode(double working) const;

    // The inverse of encode: a file value in [0,1] back to working space
    // (Floyd-Steinberg dithering carries its error there, as povray does).
    double decode(double file) const;

    // Working space -> linear light (identity when gamma handling is off,
    // as for pre-3.7 scenes without assumed_gamma).
    double toLinear(double working) const;

  private:
    double assumedGamma_ = 1.0;
    Curve curve_ = Curve::SRGB;
    double fileGamma_ = 2.2;
};

}  // namespace frameray::image
