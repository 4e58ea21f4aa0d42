#include "apps/assemble_command.h"

#include <cstdio>

#include "apps/scene_loading.h"
#include "output/atomic_file.h"
#include "output/tile_assembly.h"

namespace fluence::app {

int runAssemble(const AssembleOptions& opt) {
    try {
        output::assembleTiles(opt.tiles, opt.output);
    } catch (const output::TileReadError& e) {
        printError(e.what());
        return kExitMissingInput;
    } catch (const output::TileMismatchError& e) {
        printError(e.what());
        return kExitScene;
    } catch (const output::OutputError& e) {
        printError(e.what());
        return kExitOutput;
    }
    std::printf("fluence: assembled %zu tiles into %s\n", opt.tiles.size(), opt.output.c_str());
    return kExitOk;
}

}  // namespace fluence::app
