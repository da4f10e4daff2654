// Everything one frame's parse produces: the input of render::World.
#pragma once

#include <memory>
#include <optional>
#include <vector>

#include "scene/atmosphere.h"
#include "scene/camera.h"
#include "scene/lights.h"
#include "scene/object.h"
#include "scene/photon_settings.h"
#include "scene/radiosity.h"

namespace frameray::scene {

struct GlobalSettings {
    // Unset means "not given in the scene": the 3.7 defaulting rules apply
    // (see image/gamma).
    double assumedGamma = 0;
    bool assumedGammaSet = false;
    RGB ambientLight{1.0};
    int maxTraceLevel = 5;
    double adcBailout = 1.0 / 255.0;
    // The wavelengths irid's thin film interferes at, per channel
    // (povray 3.7's effective default, measured: <0.70, 0.52, 0.48>, not
    // the <0.25, 0.18, 0.14> older documents give).
    RGB iridWavelength{0.70, 0.52, 0.48};
    // Set by `radiosity { }`: only then is any radiosity computed.
    std::optional<RadiositySettings> radiosity;
    // Photon mapping, when the scene turns it on (render/photons.h).
    std::optional<PhotonSettings> photons;
    // Millimetres per scene unit: the scale subsurface light transport
    // sees (povray 3.7's default 10).
    double mmPerUnit = 10.0;
    // subsurface { samples D, S  radiosity B }: only then do finishes with
    // subsurface carry light under their surface (render/subsurface.h).
    struct Subsurface {
        int samplesDiffuse = 50;  // povray 3.7's defaults
        int samplesSingle = 50;
        bool radiosity = false;  // the radiosity light enters under the surface too
    };
    std::optional<Subsurface> subsurface;
};

struct Scene {
    Camera camera;
    std::vector<Light> lights;
    std::vector<std::shared_ptr<const Object>> objects;
    GlobalSettings globals;
    // Black and clear by default: only alpha output (+UA) sees the clear
    // part (measured: a 3.7 scene without background is transparent).
    Color background{RGB(0.0), 0.0, 1.0};
    Atmosphere atmosphere;         // fogs, sky sphere, rainbows
    double languageVersion = 3.7;  // the #version in force at the end of parse
    bool versionDeclared = false;  // by #version or the Version option

    // The version the image is made by: povray 3.7 renders a scene that
    // declares none as a pre-3.7 one (measured: a scene without #version
    // renders as with `#version 3.6`: no gamma handling, 3.6's filter and
    // sky), though it parses it as 3.7.
    double renderVersion() const { return versionDeclared ? languageVersion : 3.62; }
};

}  // namespace frameray::scene
