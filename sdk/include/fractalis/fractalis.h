/* fractalis/fractalis.h — the whole scene SDK in one include. */
#ifndef FRACTALIS_FRACTALIS_H
#define FRACTALIS_FRACTALIS_H

#include "fractalis/abi.h"
#include "fractalis/entry.h"
#include "fractalis/helpers.h"
#include "fractalis/param.h"
#include "fractalis/scene.h"

#endif /* FRACTALIS_FRACTALIS_H */
