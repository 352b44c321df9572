/**
 * @file c2b_iges.h
 * IGES 5.3 export of NURBS surfaces (entity 128, rational B-spline surface).
 *
 * The file has the five fixed 80-column sections of IGES 5.3 (US PRO/IPO-100, 1996,
 * chapter 2): Start, Global (the 25 fields of section 2.2.4), Directory Entry (one
 * two-line entry), Parameter Data (section 4.24, entity 128) and Terminate. No token
 * is split across records; numbers are written with the shortest decimal form that
 * reads back to the same double (at most 17 significant digits).
 *
 * Periodic directions are written in their unwrapped, non-periodic form (see
 * c2b_nurbs.h): n + p poles, the first p repeated at the end, the flat knot vector of
 * n + 2p + 1 values, the upper index K = n + p - 1, with the PROP4/PROP5 "periodic"
 * and PROP1/PROP2 "closed" flags set. The geometry is exactly that of the
 * C2Blend surface, so a reader that ignores the flags still gets the right surface.
 *
 * @name IGES export
 * @{
 */
#ifndef C2B_IGES_H
#define C2B_IGES_H

#include "c2b_error.h"
#include "c2b_nurbs.h"

#ifdef __cplusplus
extern "C" {
#endif

/**
 * Minimum user-intended resolution written to the Global section (field 19), relative to
 * the approximate maximum coordinate (field 20), i.e. resolution = this x max |pole
 * coordinate| (in model units). OpenCASCADE uses the field as its read precision.
 */
#define C2B_IGES_RESOLUTION_REL 1e-9
/** Resolution written when every pole coordinate is zero (model units). */
#define C2B_IGES_RESOLUTION_MIN 1e-12
/** Largest sequence number of a record (7 columns); longer sections give C2B_ERR_LIMIT. */
#define C2B_IGES_MAX_RECORDS 9999999L

/**
 * Write surface `s` as a single IGES 5.3 entity 128 into `path`.
 *
 * The file is first written to a temporary file in the same directory (`path` followed by
 * ".tmp-XXXXXX", made by mkstemp), flushed to disk with fsync and renamed over `path`
 * only when complete. On any failure the temporary file is removed and an existing file
 * at `path` is left untouched. A new file gets mode 0644; a replaced regular file keeps
 * its mode. A symbolic link at `path` is replaced by the file, not followed.
 *
 * The Global section names the system "C2Blend", the file by the last component of
 * `path` (printable ASCII; other bytes become '_', truncated to fit one record), the
 * date of writing (UTC), version flag 11 (IGES 5.3) and the units.
 *
 * @param s      the surface (not modified).
 * @param path   target file name (not NULL, not empty).
 * @param units  model units of the pole coordinates as an IGES unit name, case-insensitive:
 *               "IN" or "INCH" (flag 1), "MM" (2), "FT" (4), "MI" (5), "M" (6), "KM" (7),
 *               "MIL" (8), "UM" (9), "CM" (10), "UIN" (11); NULL means "MM".
 *               Coordinates are written unscaled: readers scale by the unit.
 * @param err    optional error record.
 * @return C2B_OK;
 *         C2B_ERR_ARG if `s` or `path` is NULL, `path` is empty, `units` is not one of
 *         the names above, or a pole, weight or knot is not finite;
 *         C2B_ERR_LIMIT if the Parameter Data section would exceed
 *         ::C2B_IGES_MAX_RECORDS records;
 *         C2B_ERR_NOMEM if the temporary name cannot be allocated;
 *         C2B_ERR_IO if the temporary file cannot be created, written, synced or closed,
 *         or the rename fails (the message names the file and the system error).
 */
c2b_status c2b_iges_write_surface(const c2b_nurbs_surface *s, const char *path,
                                  const char *units, c2b_error *err);

/** @} */

#ifdef __cplusplus
}
#endif
#endif
