/**
 * @file c2b_constants.h
 * Mathematical constants (C11 does not define M_PI).
 */
#ifndef C2B_CONSTANTS_H
#define C2B_CONSTANTS_H

#define C2B_PI 3.14159265358979323846264338327950288

#endif
