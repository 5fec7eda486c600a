#pragma once

#include "core/backup/BackupWiring.h"
#include "core/backup/ControllerBackup.h"

#include <string>
#include <vector>

namespace m350::backup {

// machine.toml for an imported backup: dialect m350, the libraries the backup has (slib-g.nc,
// slib-m.nc; slibuser.nc loads because it is in the folder), the magazine and IO links (importWiring), and the simulated world's
// facts no file gives, each stated with a comment and listed for review:
//   [homing] switch_distance   how far each axis stands from its home switch at power-on
//   [tool_setter] top, radius  chosen so that the tools' stored Z offsets (params 930-945,
//                              973-992: machine Z where each tripped the setter) are true
//   [tools] length             the stored offset minus the setter's top; 60 mm for a tool never set
//   [floating_setter] top      10 mm below the fixed setter's top, when the floating input is wired
struct ImportedMachine {
    std::string text;
    Message magazine; // what became of param 802
    std::vector<std::string> libraries;
    std::vector<ReviewItem> review;
    std::vector<Message> unsupported;
};

ImportedMachine formatImportedMachine(const ControllerBackup& backup);

} // namespace m350::backup
