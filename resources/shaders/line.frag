#version 330 core
// Past parts of a path solid, future parts dashed and fainter, each switchable by its alpha.
in vec4 vColour;
in vec2 vTimeDistance;
in float vAcross;

uniform float uTime;         // s
uniform float uPastAlpha;    // 0 hides what lies before uTime
uniform float uFutureAlpha;  // 0 hides what lies after it
uniform float uDashPeriod;   // m along the path; 0 = solid
uniform float uWidth;        // pixels

out vec4 fragColour;

void main()
{
    float alpha = vColour.a;
    if (vTimeDistance.x > uTime) {
        alpha *= uFutureAlpha;
        if (uDashPeriod > 0.0 && fract(vTimeDistance.y / uDashPeriod) > 0.55) discard;
    } else {
        alpha *= uPastAlpha;
    }
    // Smooth edges over about one pixel.
    float edge = 1.0 - smoothstep(uWidth / (uWidth + 1.0) - 1.0 / (uWidth + 1.0), 1.0, abs(vAcross));
    alpha *= edge;
    if (alpha <= 0.004) discard;
    fragColour = vec4(vColour.rgb, alpha);
}
