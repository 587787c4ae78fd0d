/* The kinds of surface the scattering layer knows (kernels/material.h says what each does; the
 * host's scene/surface_kinds.h which materials are of which), as a face's SpecularFace names
 * them. Shared by the host and the kernels. */
#ifndef RADIOSITY_MATERIAL_KINDS_H
#define RADIOSITY_MATERIAL_KINDS_H

#define RAD_SPECULAR_NONE 0u       /* diffuse: the radiosity pass carries its light */
#define RAD_SPECULAR_MIRROR 1u     /* colour: F0; w: unused */
#define RAD_SPECULAR_GLOSSY 2u     /* a rough metal: colour F0; w: GGX alpha */
#define RAD_SPECULAR_GLASS 3u      /* a solid that refracts: colour the tint; w: IOR */
#define RAD_SPECULAR_THIN_GLASS 4u /* a thin pane: colour the tint; w: IOR */
/* A perfect retroreflector: light goes back the way it came, times colour. No glTF material maps
 * to it; tests add it (tests/test_added_kind.cpp) to show what a new kind takes. */
#define RAD_SPECULAR_RETROREFLECTOR 5u

#endif
