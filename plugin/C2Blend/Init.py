# SPDX-License-Identifier: LGPL-2.1-or-later
# C2Blend workbench, application part: nothing GUI here, so documents with C2Blend
# objects recompute in freecadcmd. The scripting API is `import C2Blend`.
