#version 330 core
// Widens each line segment to a quad uWidth pixels wide, with a coordinate across it for smooth edges.
layout(lines) in;
layout(triangle_strip, max_vertices = 4) out;

uniform vec2 uViewport;  // pixels
uniform float uWidth;    // pixels

in vec4 gColour[];
in vec2 gTimeDistance[];

out vec4 vColour;
out vec2 vTimeDistance;
out float vAcross;

void main()
{
    vec4 p0 = gl_in[0].gl_Position;
    vec4 p1 = gl_in[1].gl_Position;
    if (p0.w <= 0.0 || p1.w <= 0.0) return;  // behind the eye
    vec2 s0 = p0.xy / p0.w * uViewport;
    vec2 s1 = p1.xy / p1.w * uViewport;
    vec2 d = s1 - s0;
    if (dot(d, d) < 1e-8) d = vec2(1.0, 0.0);
    vec2 side = normalize(vec2(-d.y, d.x)) * (uWidth + 1.0) / uViewport;
    for (int k = 0; k < 2; ++k) {
        vec4 p = k == 0 ? p0 : p1;
        for (int s = -1; s <= 1; s += 2) {
            vColour = gColour[k];
            vTimeDistance = gTimeDistance[k];
            vAcross = float(s);
            gl_Position = vec4(p.xy + float(s) * side * p.w, p.zw);
            EmitVertex();
        }
    }
    EndPrimitive();
}
