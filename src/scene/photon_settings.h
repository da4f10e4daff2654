// POV-Ray 3.7's photon mapping settings: the global block that turns it
// on and tunes shooting and gathering, an object's role (a target photons
// are shot at, whether it reflects, refracts, collects or lets them pass)
// and a light's (which kinds of photons it shoots). render/photons.h does
// the work; these are the parsed values only.
#pragma once

#include <cstdint>
#include <memory>
#include <string>
#include <string_view>

namespace frameray::scene {

// povray keeps `refraction` and `reflection` as two flags each, on and
// off, in objects and lights alike: a block that does not mention one
// leaves both unset.
enum class PhotonToggle : std::uint8_t { Unset, On, Off };

// Whether an object refracts (or reflects) a light's photons: one of the
// two says on and neither says off (povray 3.7's rule, the same when it
// picks the targets a light shoots at, when a photon meets a surface and
// when a shadow ray meets a target).
constexpr bool photonsActive(PhotonToggle object, PhotonToggle light) {
    return (object == PhotonToggle::On || light == PhotonToggle::On) &&
           object != PhotonToggle::Off && light != PhotonToggle::Off;
}

// global_settings { photons { ... } }. Defaults are povray 3.7's.
struct PhotonSettings {
    // Distance between photons on a target at its distance from the light;
    // 0 when the scene gives `count` instead.
    double spacing = 0;
    int count = 0;  // photons to shoot, povray picking the spacing
    int gatherMin = 20;
    int gatherMax = 100;
    double jitter = 0.4;     // of the angular spacing, per photon
    int maxTraceLevel = -1;  // -1: the scene's max_trace_level
    double adcBailout = -1;  // negative: the scene's adc_bailout
    // Fraction of the target's cone shot before stopping is allowed (povray 3.7:
    // 0.5 unless given; measured: advanced/optics.pov shoots 16971 photons at
    // its media box, 2553 with autostop 0).
    double autostop = 0.5;
    // expand_thresholds: when a gather's wider search is kept
    // (render/photons.cpp, adaptiveGather).
    double expandIncrease = 0.2;
    int expandMin = 40;
    double radius = 0;  // gather radius; 0: estimated from the photons
    double radiusMultiplier = 1.0;
    double mediaRadius = 0;
    double mediaRadiusMultiplier = 1.0;
    // media max_steps [, factor]: photons are left in media along the paths
    // of photons that have bounced, at most max_steps per interval, factor
    // times the surface spacing apart. 0: no media photons.
    int mediaMaxSteps = 0;
    double mediaFactor = 1.0;
    // save_file: where the photon maps go once shot (absolute; empty: not
    // saved). load_file: the bytes of a map saved so, read when parsed
    // (null: shoot); loadFile names it in messages. Given both, povray
    // loads and does not save.
    std::string saveFile;
    std::string loadFile;
    std::shared_ptr<const std::string> loaded;
};

// The first bytes of frameray's photon map files (render/photon_file.h):
// the parser refuses other files (povray's own) where load_file names them.
inline constexpr std::string_view kPhotonFileMagic = "frameray photon map 1\n";

// An object's photons { ... } block. povray's defaults: no target,
// reflection and refraction unset (photonsActive), collect on.
struct ObjectPhotons {
    bool given = false;  // a photons block was written (CSG children inherit it otherwise)
    double target = 0;   // spacing multiplier; 0: photons are not shot at it
    PhotonToggle refraction = PhotonToggle::Unset;
    PhotonToggle reflection = PhotonToggle::Unset;
    bool collect = true;
    bool passThrough = false;
    bool splitUnion = true;
};

// A light's photons { ... } block. Unset, a light shoots at targets that
// say refraction or reflection on (measured: a target with refraction on
// gets photons from a light that says nothing); `on` makes every object
// that does not say off refract or reflect its photons (povray 3.7:
// advanced/optics.pov's mirrors and media box have no flags of their own).
struct LightPhotons {
    PhotonToggle refraction = PhotonToggle::Unset;
    PhotonToggle reflection = PhotonToggle::Unset;
    bool areaLight = false;  // shoot from every sample of an area light
};

}  // namespace frameray::scene
