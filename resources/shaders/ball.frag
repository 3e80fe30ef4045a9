#version 330 core
// Phenolic balls, ray-traced on their impostor quad: glossy Phong under the two lamps, a band for
// stripes, a white disc with the number on both ends of the body x axis, red dots on the cue ball's
// six axes, the silhouette antialiased over one pixel. Built with GHOST for the translucent ghost
// balls, which keep the depth of their impostor quad (it lies just in front of the sphere): a shader
// that writes gl_FragDepth loses the software rasteriser's early depth test, and the ghosts, many
// and overlapping, are drawn after everything they could hide.
in vec3 vQuadPoint;
flat in vec4 vCentreRadius;
flat in vec4 vOrientation;
flat in vec4 vColourNumber;
flat in vec4 vFlags;

uniform mat4 uViewProjection;
uniform vec3 uEye;
uniform vec3 uLights[2];
uniform float uPixelAngle;  // radians per pixel, vertically
uniform sampler2D uDigits;  // 4 x 4 cells, the numbers 0-15 as coverage in the red channel

out vec4 fragColour;

const vec3 WHITE = vec3(0.95, 0.94, 0.89);
const float DISC_COS = 0.9;     // angular radius of the number disc: acos(0.9) = 25.8 deg
const float DISC_SIN = 0.43589; // sin(acos(0.9))

// Rotates v by the inverse of the unit quaternion q.
vec3 rotateInverse(vec4 q, vec3 v)
{
    vec3 u = -q.xyz;
    return v + 2.0 * cross(u, cross(u, v) + q.w * v);
}

void main()
{
    vec3 centre = vCentreRadius.xyz;
    float r = vCentreRadius.w;
    vec3 dir = normalize(vQuadPoint - uEye);
    vec3 oc = uEye - centre;
    float b = dot(oc, dir);
    float miss2 = dot(oc, oc) - b * b;  // squared distance from the centre to the ray
    float miss = sqrt(max(miss2, 0.0));
    float pixel = -b * uPixelAngle;     // m per pixel at the ball's distance
    float coverage = clamp((r - miss) / pixel + 0.5, 0.0, 1.0);
    if (coverage <= 0.0) discard;
    // On the sphere where the ray meets it; at the rim, the nearest point of the outline.
    float h = max(r * r - miss2, 0.0);
    vec3 p = uEye + (-b - sqrt(h)) * dir;
    vec3 n = normalize(p - centre);
#ifndef GHOST
    vec4 clip = uViewProjection * vec4(p, 1.0);
    gl_FragDepth = clamp(0.5 + 0.5 * clip.z / clip.w, 0.0, 1.0);
#endif

    vec3 l = rotateInverse(vOrientation, n);
    vec3 base = vColourNumber.rgb;
    float aa = 0.02;
    if (vFlags.x > 0.5) base = mix(base, WHITE, smoothstep(0.52 - aa, 0.52 + aa, abs(l.z)));
    if (vFlags.y > 0.5) {
        vec3 a = abs(l);
        float m = max(a.x, max(a.y, a.z));
        base = mix(base, vec3(0.75, 0.05, 0.05), smoothstep(0.980, 0.984, m));
    }
    int number = int(vColourNumber.a + 0.5);
    if (number > 0) {
        float c = abs(l.x);
        float disc = smoothstep(DISC_COS - 0.006, DISC_COS + 0.006, c);
        // Disc coordinates, upright when the disc is seen from outside with the body z axis up.
        vec2 uv = vec2(l.y * sign(l.x), l.z) / DISC_SIN * 0.62;
        vec2 cell = vec2(float(number % 4), float(number / 4));
        vec2 atlas = (cell + vec2(0.5 + 0.5 * uv.x, 0.5 - 0.5 * uv.y)) / 4.0;
        float ink = (abs(uv.x) < 1.0 && abs(uv.y) < 1.0) ? texture(uDigits, atlas).r : 0.0;
        base = mix(base, mix(WHITE, vec3(0.02), ink), disc);
    }

    vec3 toEye = -dir;
    vec3 light = 0.22 * base;
    for (int i = 0; i < 2; ++i) {
        vec3 d = uLights[i] - p;
        float falloff = 1.0 / (1.0 + 0.35 * dot(d.xy, d.xy));
        vec3 towards = normalize(d);
        float diffuse = max(dot(n, towards), 0.0);
        float spec = pow(max(dot(reflect(-towards, n), toEye), 0.0), 90.0);
        light += falloff * (0.75 * diffuse * base + 0.8 * spec * vec3(1.0));
    }
    // A faint reflection of the room at grazing angles.
    float rim = pow(1.0 - max(dot(n, toEye), 0.0), 3.0);
    light += 0.08 * rim * vec3(0.8, 0.85, 0.9);
    if (vFlags.z > 0.5) light += rim * vec3(1.0, 0.85, 0.2) + 0.08 * vec3(1.0, 0.9, 0.4);
    fragColour = vec4(light, vFlags.w * coverage);
}
