// The entry points of every command; each is defined in its own cmd_*.cc.
#ifndef LINEMAP_TOOLS_LINEMAP_COMMANDS_H_
#define LINEMAP_TOOLS_LINEMAP_COMMANDS_H_

#include <string>
#include <vector>

#include "tools/linemap/cli.h"

namespace linemap::cli {

#define LINEMAP_DECLARE_COMMAND(Name)     \
  extern const CommandSpec k##Name##Spec; \
  int Run##Name(const std::vector<std::string>& args)

LINEMAP_DECLARE_COMMAND(Info);
LINEMAP_DECLARE_COMMAND(Lines);
LINEMAP_DECLARE_COMMAND(Segment);
LINEMAP_DECLARE_COMMAND(Encode);
LINEMAP_DECLARE_COMMAND(Decode);
LINEMAP_DECLARE_COMMAND(Export);
LINEMAP_DECLARE_COMMAND(Eval);
LINEMAP_DECLARE_COMMAND(Plan);
LINEMAP_DECLARE_COMMAND(Bench);

#undef LINEMAP_DECLARE_COMMAND

}  // namespace linemap::cli

#endif  // LINEMAP_TOOLS_LINEMAP_COMMANDS_H_
