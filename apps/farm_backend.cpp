#include "apps/farm_backend.h"

#include "apps/farm_local_backend.h"
#include "apps/farm_slurm_backend.h"

namespace fluence::app {

std::unique_ptr<FarmBackend> makeFarmBackend(const std::string& name, int maxLocalJobs) {
    if (name == "slurm") return std::make_unique<SlurmFarmBackend>();
    if (name == "local") return std::make_unique<LocalFarmBackend>(maxLocalJobs);
    throw std::invalid_argument("unknown farm backend '" + name + "' (available: " + farmBackendNames() + ")");
}

std::string farmBackendNames() { return "slurm, local"; }

}  // namespace fluence::app
