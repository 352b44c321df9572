# SPDX-License-Identifier: LGPL-2.1-or-later
"""C2Blend workbench package: geometry (headless), objects, and GUI parts."""
