// withSkinFriction: the volumes of a VTK volume file (.vtu, .vtk, EnSight, Exodus, a .pvd of
// them) handed out as their boundary surfaces with the derived skin-friction
// (skin_friction.h). Every boundary face is taken as a wall; the wall velocity is that of the
// face's points where the volume has a point velocity (alone or beside the cells' own, as
// foamToVTK writes both), else zero (a wall at rest).
#include "io/reader/skin_friction.h"
#include "io/reader/vtk_sources.h"

#include "core/errors.h"

#include <vtkCompositeDataIterator.h>
#include <vtkCompositeDataSet.h>
#include <vtkDataSet.h>

#include <sstream>

namespace flowsurf::io::detail {

namespace {

class VolumeWallSource final : public StepSource {
public:
    VolumeWallSource(std::unique_ptr<StepSource> inner, SkinFrictionOptions options, std::string format)
        : StepSource(inner->path(), std::move(format)), inner_(std::move(inner)), options_(std::move(options)) {
        times_ = inner_->times();
    }

    vtkSmartPointer<vtkDataObject> readStep(size_t index) override {
        vtkSmartPointer<vtkDataObject> step = inner_->readStep(index);
        if (auto* ds = vtkDataSet::SafeDownCast(step)) {
            if (!hasVolumeCells(ds)) throw noVolume();
            return newBoundaryWithSkinFriction(ds, options_, path_);
        }
        auto* composite = vtkCompositeDataSet::SafeDownCast(step);
        bool any = false;
        if (composite) {
            // Surfaces in the file (a block of boundary faces beside the volume) stay as they are.
            auto it = vtkSmartPointer<vtkCompositeDataIterator>::Take(composite->NewIterator());
            it->SkipEmptyNodesOn();
            for (it->InitTraversal(); !it->IsDoneWithTraversal(); it->GoToNextItem()) {
                auto* leaf = vtkDataSet::SafeDownCast(it->GetCurrentDataObject());
                if (!leaf || !hasVolumeCells(leaf)) continue;
                composite->SetDataSet(it, newBoundaryWithSkinFriction(leaf, options_, path_));
                any = true;
            }
        }
        if (!any) throw noVolume();
        return step;
    }

private:
    FormatError noVolume() const {
        return FormatError(path_ + ": --field skin-friction needs a volume mesh with its velocity (an OpenFOAM "
                                   "case, a .vtu/.vtk volume, EnSight or Exodus volume parts); this " +
                           inner_->format() + " holds no volume cells");
    }

    std::unique_ptr<StepSource> inner_;
    SkinFrictionOptions options_;
};

}  // namespace

std::unique_ptr<StepSource> withSkinFriction(std::unique_ptr<StepSource> inner, const SourceOptions& options) {
    SkinFrictionOptions sf;
    sf.viscosity = options.viscosity;
    sf.warn = warnOnce;
    std::ostringstream nu;
    nu << options.viscosity;
    const std::string format = inner->format() + " (skin-friction on the boundary surface: " +
                               (options.viscosity > 0 ? "nu = " + nu.str() + " m^2/s from --viscosity"
                                                      : "no viscosity given, relative magnitude") + ")";
    return std::make_unique<VolumeWallSource>(std::move(inner), sf, format);
}

}  // namespace flowsurf::io::detail
