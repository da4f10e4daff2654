#include "app/version.h"

#include <OpenEXR/OpenEXRConfig.h>
#include <OpenImageIO/oiioversion.h>
#include <embree3/rtcore_config.h>
#include <fmt/format.h>
#include <png.h>
#include <tbb/version.h>

namespace frameray::app {

std::string versionText() {
    // Embree, OpenImageIO, OpenEXR and libpng as built against (OpenImageIO
    // is loaded only when an image is first encoded, so asking the library
    // itself would cost --version that load); oneTBB as loaded now.
    return fmt::format(
        "frameray {} (POV-Ray 3.7 scene language)\n"
        "Embree {}\n"
        "oneTBB {} (interface {})\n"
        "OpenImageIO {}\n"
        "OpenEXR {}\n"
        "libpng {}\n"
        "fmt {}.{}.{}\n",
        FRAMERAY_VERSION, RTC_VERSION_STRING, TBB_runtime_version(), TBB_VERSION_STRING,
        OIIO_VERSION_STRING, OPENEXR_VERSION_STRING, PNG_LIBPNG_VER_STRING, FMT_VERSION / 10000,
        FMT_VERSION / 100 % 100, FMT_VERSION % 100);
}

}  // namespace frameray::app
