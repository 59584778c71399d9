/* vis_painter.c - the painter's algorithm: faces drawn far to near,
 * ordered by "jeffsort", the seed's counting sort (Jeff Franklin): a
 * histogram of the quantised depth keys, its prefix sums, then each face
 * placed at its bucket's next slot.  Linear time, stable, and its memory
 * is one count per bucket plus the order array.  Keys are the mean
 * depth of the face's vertices (the seed's "midpoint"), so the seed's
 * wall-and-pillar case fails exactly as the seed says it does. */
#include "r8int.h"

void r8_jeffsort(r8_state *st)
{
    r8_u16 i, sum = 0;
    for (i = 0; i < R8_JEFF_BUCKETS; i++)
        st->jeff[i] = 0;
    for (i = 0; i < st->npoly; i++)
        st->jeff[st->poly[i].key]++;
    for (i = 0; i < R8_JEFF_BUCKETS; i++) {   /* counts -> first slots */
        r8_u16 c = st->jeff[i];
        st->jeff[i] = sum;
        sum = (r8_u16)(sum + c);
    }
    for (i = 0; i < st->npoly; i++)
        st->order[st->jeff[st->poly[i].key]++] = i;
}
